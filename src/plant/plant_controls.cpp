#include "duet/plant/plant_controls.hpp"

#include <algorithm>
#include <array>
#include <charconv>

namespace duet::plant {
namespace {

std::string number(double value) {
  std::array<char, 32> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} ? std::string(text.data(), end) : std::string{"?"};
}

std::string with_unit(double value, const std::string& unit) {
  return unit.empty() ? number(value) : number(value) + " " + unit;
}

}  // namespace

Status check_disturbance(const std::vector<DisturbanceKind>& offered, const Disturbance& disturbance) {
  const auto kind = std::find_if(offered.begin(), offered.end(),
                                 [&](const DisturbanceKind& candidate) { return candidate.name == disturbance.name; });
  if (kind == offered.end()) {
    std::string names;
    for (const DisturbanceKind& candidate : offered) names += (names.empty() ? "" : ", ") + candidate.name;
    return Failure{"no disturbance named '" + disturbance.name + "' (" +
                   (names.empty() ? std::string{"the plant offers none"} : "offered: " + names) + ")"};
  }
  if (disturbance.arguments.size() != kind->arguments.size()) {
    return Failure{kind->name + " takes " + std::to_string(kind->arguments.size()) + " arguments, not " +
                   std::to_string(disturbance.arguments.size())};
  }
  for (std::size_t k = 0; k < kind->arguments.size(); ++k) {
    const DisturbanceArgument& argument = kind->arguments[k];
    const double value = disturbance.arguments[k];
    if (!(value >= argument.minimum && value <= argument.maximum)) {  // NaN too
      return Failure{kind->name + ": " + argument.name + " = " + with_unit(value, argument.unit) + " is outside " +
                     number(argument.minimum) + " to " + with_unit(argument.maximum, argument.unit)};
    }
  }
  return done();
}

PlantControls::PlantControls(std::vector<DisturbanceKind> offered) : offered_(std::move(offered)) {}

PlantControls::~PlantControls() = default;

Result<PlantControls::Ticket> PlantControls::request(Disturbance disturbance, Answer answer) {
  if (Status checked = check_disturbance(offered_, disturbance); !checked) return Failure{checked.error()};
  const std::lock_guard lock{mutex_};
  if (!served_) return Failure{"the plant is not running (no firmware is connected to it)"};
  const Ticket ticket = next_ticket_++;
  waiting_.push_back({ticket, std::move(disturbance), std::move(answer)});
  return ticket;
}

bool PlantControls::withdraw(Ticket ticket) {
  const std::lock_guard lock{mutex_};
  const auto found =
      std::find_if(waiting_.begin(), waiting_.end(), [ticket](const Waiting& one) { return one.ticket == ticket; });
  if (found == waiting_.end()) return false;
  waiting_.erase(found);
  return true;
}

std::vector<AppliedDisturbance> PlantControls::applied() const {
  const std::lock_guard lock{mutex_};
  return applied_;
}

void PlantControls::attach() {
  const std::lock_guard lock{mutex_};
  served_ = true;
}

void PlantControls::detach() {
  std::vector<Waiting> unanswered;
  {
    const std::lock_guard lock{mutex_};
    served_ = false;
    unanswered.swap(waiting_);
  }
  for (const Waiting& one : unanswered) {
    one.answer(Failure{one.disturbance.name + " was not applied: the plant stopped running first"});
  }
}

void PlantControls::apply(Plant& plant, double time_s) {
  std::vector<Waiting> taken;
  {
    const std::lock_guard lock{mutex_};
    if (waiting_.empty()) return;  // the common case: one lock, nothing else
    taken.swap(waiting_);
    for (const Waiting& one : taken) applied_.push_back({one.disturbance, time_s});
  }
  // Answered only once the plant has them all, outside the lock: an answer may ask for more.
  for (const Waiting& one : taken) plant.disturb(one.disturbance, time_s);
  for (const Waiting& one : taken) one.answer(AppliedDisturbance{one.disturbance, time_s});
}

ControlledPlant::ControlledPlant(std::unique_ptr<Plant> behind, PlantControls& controls)
    : behind_(std::move(behind)), controls_(controls) {
  controls_.attach();
}

ControlledPlant::~ControlledPlant() { controls_.detach(); }

void ControlledPlant::advance(double time_s, const RaiseInterrupt& raise) {
  controls_.apply(*behind_, time_s);
  behind_->advance(time_s, raise);
}

}  // namespace duet::plant
