#include "import_context.hpp"

#include <cmath>
#include <functional>
#include <set>

#include "duet/simulink_import/builtin_defaults.hpp"

namespace duet::simulink_import {
std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\n") - first + 1);
}

std::string stored_or(const Block& block, const char* name, const char* otherwise) {
  const auto found = block.parameters.find(name);
  return found == block.parameters.end() ? std::string{otherwise} : trimmed(found->second);
}

bool is_duet_type(const std::string& type) {
  static const std::set<std::string, std::less<>> types{"double", "single", "int8",   "int16",  "int32",
                                                        "uint8",  "uint16", "uint32", "boolean"};
  return types.count(type) != 0;
}

std::string type_name(const Block& block) {
  const auto linked = block.parameters.find("SourceType");
  return block.type == "Reference" && linked != block.parameters.end() ? linked->second : block.type;
}

std::optional<std::string> ImportContext::raw(const std::string& name) {
  if (const auto masked = block_.mask_parameters.find(name); masked != block_.mask_parameters.end())
    return masked->second;
  if (const auto stored = block_.parameters.find(name); stored != block_.parameters.end()) return stored->second;
  const SimulinkModel& source = model_.source();
  if (const auto type = source.defaults.find(block_.type); type != source.defaults.end()) {
    if (const auto found = type->second.find(name); found != type->second.end()) return found->second;
  }
  const std::string release = source.release.empty() && source.format == "mdl (classic)" ? "R2019b" : source.release;
  if (const auto built_in = builtin_default(block_.type, name, release)) return std::string{*built_in};
  refuse("its parameter " + name + " is not in the file, and duet knows no default for it");
  return std::nullopt;
}

std::optional<Value> ImportContext::value(const std::string& name) {
  const auto text = raw(name);
  if (!text) return std::nullopt;
  auto evaluated = evaluate(*text, workspace_);
  if (!evaluated) {
    refuse(name + " '" + *text + "': " + evaluated.error());
    return std::nullopt;
  }
  if (evaluated.value().is_struct) {
    refuse(name + " '" + *text + "' is a struct, not a number");
    return std::nullopt;
  }
  return std::move(evaluated).value();
}

std::optional<double> ImportContext::scalar(const std::string& name) {
  const auto evaluated = value(name);
  if (!evaluated) return std::nullopt;
  if (!evaluated->is_scalar()) {
    refuse(name + " is " + evaluated->size_text() + ", where duet takes one number");
    return std::nullopt;
  }
  return evaluated->elements.front();
}

std::optional<std::string> ImportContext::parameter(const std::string& name) {
  const auto text = raw(name);
  if (!text) return std::nullopt;
  return model_.parameter_text(*this, name, *text);
}

bool ImportContext::require(const std::string& name, const std::string& expected, const std::string& what) {
  const auto text = raw(name);
  if (!text) return false;
  if (trimmed(*text) == expected) return true;
  refuse(name + " is '" + *text + "': " + what);
  return false;
}

std::optional<std::string> ImportContext::input(std::size_t port) {
  if (port == 0 || port > inputs_.size() || inputs_[port - 1].empty()) {
    refuse("its input " + std::to_string(port) + " is not connected");
    return std::nullopt;
  }
  return inputs_[port - 1];
}

std::string ImportContext::output(std::size_t port) {
  if (port > outputs_.size()) outputs_.resize(port);
  if (outputs_[port - 1].empty()) outputs_[port - 1] = new_signal_name(block_name + "_unused" + std::to_string(port));
  return outputs_[port - 1];
}

std::optional<std::string> ImportContext::period(const std::string& name) {
  const auto text = raw(name);
  if (!text) return std::nullopt;
  if (trimmed(*text) == "-1" || trimmed(*text) == "-1.0000000000000000") return std::string{};
  const auto sample = value(name);
  if (!sample) return std::nullopt;
  if (sample->count() == 2 && sample->elements[1] != 0) {
    refuse(name + " '" + *text + "' has an offset, which duet's rates do not");
    return std::nullopt;
  }
  if (sample->count() != 1 && sample->count() != 2) {
    refuse(name + " '" + *text + "' is neither a period nor [period, offset]");
    return std::nullopt;
  }
  const double seconds = sample->elements[0];
  if (seconds == -1) return std::string{};
  if (std::isinf(seconds) && seconds > 0) return std::string{"period: constant"};
  if (!(seconds > 0)) {
    refuse(name + " '" + *text + "' is continuous (0): duet imports discrete models only");
    return std::nullopt;
  }
  const double microseconds = seconds * 1e6;
  const long long whole = std::llround(microseconds);
  const long long base = model_.base_period_us();
  if (std::fabs(microseconds - static_cast<double>(whole)) > 1e-6 * microseconds || whole % base != 0) {
    refuse(name + " " + *text + " s is not a whole multiple of the base period of " + std::to_string(base) + " us");
    return std::nullopt;
  }
  return whole == base ? std::string{"period: base"} : "period_us: " + std::to_string(whole);
}

void ImportContext::emit(DuetBlock block, const std::string& what) {
  if (block.name.empty()) block.name = block_name;
  block.source = path_ + " (" + type_name(block_) + ")";
  emitted_.push_back(std::move(block));
  if (!what.empty()) what_ += (what_.empty() ? "" : "; ") + what;
}

void ImportContext::refuse(const std::string& reason) {
  if (refused_) return;  // the first reason is the one to fix first
  refused_ = true;
  reason_ = reason;
}

}  // namespace duet::simulink_import
