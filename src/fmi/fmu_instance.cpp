#include "fmu_instance.hpp"

#include <dlfcn.h>

#include <array>
#include <sstream>

namespace duet::fmi {

void FmuMessages::add(std::string_view status, std::string_view message) {
  last = message;
  if (log) log(model_name + ": " + std::string{status} + ": " + std::string{message});
}

void* Symbols::find_address(const char* name) {
  void* address = dlsym(library_, name);
  if (address == nullptr) missing_ += (missing_.empty() ? "" : ", ") + std::string{name};
  return address;
}

std::string time_text(double time_s) {
  std::ostringstream text;
  text << time_s;
  return text.str();
}

Failure FmuInstance::failure(std::string_view function, std::string_view what) const {
  std::string message =
      messages_.model_name + " at t = " + time_text(time_s_) + " s: " + std::string{function} + " " + std::string{what};
  message += messages_.last.empty() ? " (the FMU logged no message)" : ": " + messages_.last;
  return Failure{std::move(message)};
}

Status FmuInstance::check(std::string_view function, int status) {
  constexpr std::array<std::string_view, 6> names = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
  switch (status) {
    case 0: return done();
    case 1:
      if (messages_.log)
        messages_.log(messages_.model_name + ": t = " + time_text(time_s_) + " s: " + std::string{function} +
                      " returned Warning");
      return done();
    case 3: failed_ = true; break;
    case 4:
      failed_ = true;
      fatal_ = true;
      break;
    default: break;  // Discard, Pending: not what duet asked for
  }
  const auto index = static_cast<std::size_t>(status);
  return failure(function,
                 "returned " + (index < names.size() ? std::string{names[index]} : "status " + std::to_string(status)));
}

Status FmuInstance::usable() const {
  if (fatal_) return Failure{messages_.model_name + " returned Fatal before: duet calls it no more"};
  if (failed_) return Failure{messages_.model_name + " failed before: duet calls it no more"};
  return done();
}

}  // namespace duet::fmi
