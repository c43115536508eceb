#include "duet/fmi/imported_fmu.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>

#include "duet/fmi/archive.hpp"
#include "duet/fmi/fmu_contents.hpp"
#include "duet/support/temporary_folder.hpp"
#include "fmu_instance.hpp"

namespace duet::fmi {
namespace {

// The FMUs that allow one instance per process (canBeInstantiatedOnlyOncePerProcess) with one alive, by token.
class OnlyOnceInstances {
 public:
  bool claim(const std::string& token) {
    const std::lock_guard lock{mutex_};
    return alive_.insert(token).second;
  }
  void release(const std::string& token) {
    const std::lock_guard lock{mutex_};
    alive_.erase(token);
  }

 private:
  std::mutex mutex_;
  std::set<std::string> alive_;
};

OnlyOnceInstances& only_once_instances() {
  static OnlyOnceInstances instances;
  return instances;
}

}  // namespace

// Freed in reverse order of making: the claim and the library after the instance (ImportedFmu's member order),
// the folder last.
struct ImportedFmu::Loaded {
  explicit Loaded(TemporaryFolder unpacked) : folder(std::move(unpacked)) {}
  Loaded(const Loaded&) = delete;
  Loaded& operator=(const Loaded&) = delete;
  ~Loaded() {
    if (library != nullptr) dlclose(library);
    if (claimed) only_once_instances().release(*claimed);
  }

  TemporaryFolder folder;
  void* library = nullptr;
  std::optional<std::string> claimed;
  FmuMessages messages;
};

ImportedFmu::ImportedFmu(ModelDescription description, std::unique_ptr<Loaded> loaded)
    : description_(std::move(description)), loaded_(std::move(loaded)) {}

ImportedFmu::~ImportedFmu() = default;

Result<std::unique_ptr<ImportedFmu>> ImportedFmu::open(const std::filesystem::path& file, FmuLog log) {
  auto archive = Archive::open(file);
  if (!archive) return Failure{archive.error()};
  auto description = read_description(archive.value(), file);
  if (!description) return Failure{description.error()};
  const std::string binary = linux_binary(description.value());
  const std::string where = file.string() + ": ";
  if (!archive.value().contains(binary)) {
    return Failure{where + "no " + binary + ": the FMU has no library for Linux x86_64 (FMI " +
                   (description.value().version == FmiVersion::v2 ? "2.0" : "3.0") + "), so duet cannot run it"};
  }
  auto folder = archive.value().extract();
  if (!folder) return Failure{folder.error()};
  auto loaded = std::make_unique<Loaded>(std::move(folder).value());
  loaded->messages.model_name = description.value().model_name;
  loaded->messages.log = std::move(log);
  // RTLD_LOCAL: two FMUs export the same names, and each must find its own.
  loaded->library = dlopen((loaded->folder.path() / binary).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (loaded->library == nullptr) return Failure{where + "cannot load " + binary + ": " + dlerror()};
  if (description.value().co_simulation.can_be_instantiated_only_once_per_process) {
    if (!only_once_instances().claim(description.value().token)) {
      return Failure{where + description.value().model_name +
                     " can be instantiated only once per process (canBeInstantiatedOnlyOncePerProcess), and an "
                     "instance is alive"};
    }
    loaded->claimed = description.value().token;
  }
  std::unique_ptr<ImportedFmu> fmu{new ImportedFmu(std::move(description).value(), std::move(loaded))};
  const std::filesystem::path& unpacked = fmu->loaded_->folder.path();
  auto instance = fmu->description_.version == FmiVersion::v2
                      ? make_fmi2_instance(fmu->loaded_->library, fmu->description_, unpacked, fmu->loaded_->messages)
                      : make_fmi3_instance(fmu->loaded_->library, fmu->description_, unpacked, fmu->loaded_->messages);
  if (!instance) return Failure{where + binary + ": " + instance.error()};
  fmu->instance_ = std::move(instance).value();
  return fmu;
}

const Variable* ImportedFmu::variable(std::string_view name) const {
  const auto found = std::find_if(description_.variables.begin(), description_.variables.end(),
                                  [name](const Variable& variable) { return variable.name == name; });
  return found == description_.variables.end() ? nullptr : &*found;
}

Status ImportedFmu::set(const Variable& variable, double value) { return instance_->set(variable, value); }

Result<double> ImportedFmu::get(const Variable& variable) { return instance_->get(variable); }

Status ImportedFmu::initialize(double start_s, double step_s, const std::function<Status()>& set_inputs) {
  if (!(step_s > 0) || !std::isfinite(step_s)) return Failure{"the communication step must be a positive time"};
  start_s_ = start_s;
  step_s_ = step_s;
  if (const std::optional<double> fixed = description_.co_simulation.fixed_internal_step_size) {
    // Several of the FMU's own steps per period, the communication points falling on the period's.
    const double ratio = step_s / *fixed;
    const double whole = std::round(ratio);
    if (whole < 1 || std::abs(ratio - whole) > 1e-9 * ratio) {
      return Failure{description_.model_name + " steps at its fixedInternalStepSize of " + time_text(*fixed) +
                     " s, which does not divide the step of " + time_text(step_s) + " s"};
    }
    step_s_ = *fixed;
  }
  if (auto entered = instance_->enter_initialization(start_s); !entered) return entered;
  if (set_inputs) {
    if (auto set = set_inputs(); !set) return set;
  }
  return instance_->exit_initialization();
}

double ImportedFmu::time() const { return start_s_ + static_cast<double>(steps_) * step_s_; }

Status ImportedFmu::advance_to(double time_s) {
  if (failure_) return Failure{*failure_};
  // Each communication point computed from the start, never summed step by step, so that none drifts.
  while (!stop_request_ && start_s_ + static_cast<double>(steps_ + 1) * step_s_ <= time_s + step_s_ * 1e-9) {
    auto stepped = instance_->step(time(), step_s_);
    if (!stepped) {
      failure_ = stepped.error();
      return Failure{*failure_};
    }
    ++steps_;
    if (stepped.value().stop_requested) {
      const std::string& last = loaded_->messages.last;
      stop_request_ = description_.model_name + " asked to stop at t = " + time_text(stepped.value().reached_s) + " s" +
                      (last.empty() ? "" : ": " + last);
    }
  }
  return done();
}

}  // namespace duet::fmi
