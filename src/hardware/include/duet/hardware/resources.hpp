#pragma once
// The resources a model's hardware blocks name, as compile-time values (docs/MODELS.md, "Hardware blocks"):
// generated code passes them as template arguments to its port's typed calls (duet/hardware/hardware.hpp), so that
// which peripheral a block reaches is settled when the firmware is compiled: no names compared at run time, and a
// resource that is malformed, or that the board does not route, is a compile error. The numbers are the STM32MP15's
// (TIM1 to TIM17, SPI1 to SPI6, ADC1 and ADC2), which the simulated robot answers to as well.
//
// Each resource also knows its name as the simulated plant calls it ("pwm:TIM1/3"): the PC's port and the plant link
// on QEMU hand it to the plant, built here at compile time.
//
// Freestanding, header-only.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace duet::hardware {

// A plant's name for a resource, at most 31 characters, built at compile time.
struct ResourceName {
  char text[32]{};
  std::uint8_t size = 0;

  [[nodiscard]] constexpr std::string_view view() const { return {text, size}; }
  constexpr ResourceName& append(std::string_view part) {
    for (const char c : part) text[size++] = c;
    return *this;
  }
  constexpr ResourceName& append_number(unsigned number) {
    if (number >= 10) append_number(number / 10);
    text[size++] = static_cast<char>('0' + number % 10);
    return *this;
  }
};

struct PwmChannel {
  std::uint8_t timer;  // TIMn
  std::uint8_t channel;
};
struct CaptureChannel {
  std::uint8_t timer;
  std::uint8_t channel;
};
struct SpiBus {
  std::uint8_t number;  // SPIn
};
struct AdcInput {
  std::uint8_t adc;  // ADCn
  std::uint8_t channel;
};
struct ExtiLine {
  std::uint8_t line;  // EXTIn
};
// A message channel to the application core; its name is the model's ("app").
struct IpcChannel {
  char name[16]{};
  std::uint8_t size = 0;
  [[nodiscard]] constexpr std::string_view view() const { return {name, size}; }
};

// What an input capture took: the counter at the edge, and which edge (true: rising).
struct CaptureReading {
  std::uint32_t count = 0;
  bool rising = true;
};

namespace detail {
// Not constexpr: reaching it in a constant evaluation is the compile error for a malformed resource.
inline unsigned no_such_resource() { return 0; }

// The number after `prefix` in `name` ("TIM12" with "TIM": 12), between `lowest` and `highest`.
consteval unsigned numbered(std::string_view name, std::string_view prefix, unsigned lowest, unsigned highest) {
  if (name.size() <= prefix.size() || name.size() > prefix.size() + 2 || name.substr(0, prefix.size()) != prefix ||
      name[prefix.size()] == '0') {
    return no_such_resource();
  }
  unsigned number = 0;
  for (const char digit : name.substr(prefix.size())) {
    if (digit < '0' || digit > '9') return no_such_resource();
    number = number * 10 + static_cast<unsigned>(digit - '0');
  }
  return number >= lowest && number <= highest ? number : no_such_resource();
}
consteval std::uint8_t in_range(unsigned number, unsigned lowest, unsigned highest) {
  return static_cast<std::uint8_t>(number >= lowest && number <= highest ? number : no_such_resource());
}
}  // namespace detail

// "TIM1", channel 1 to 4.
consteval PwmChannel pwm(std::string_view timer, unsigned channel) {
  return {static_cast<std::uint8_t>(detail::numbered(timer, "TIM", 1, 17)), detail::in_range(channel, 1, 4)};
}
consteval CaptureChannel capture(std::string_view timer, unsigned channel) {
  return {static_cast<std::uint8_t>(detail::numbered(timer, "TIM", 1, 17)), detail::in_range(channel, 1, 4)};
}
// "SPI5".
consteval SpiBus spi(std::string_view bus) { return {static_cast<std::uint8_t>(detail::numbered(bus, "SPI", 1, 6))}; }
// "ADC1", input channel 0 to 19.
consteval AdcInput adc(std::string_view converter, unsigned channel) {
  return {static_cast<std::uint8_t>(detail::numbered(converter, "ADC", 1, 2)), detail::in_range(channel, 0, 19)};
}
// "EXTI4".
consteval ExtiLine exti(std::string_view line) {
  return {line == "EXTI0" ? std::uint8_t{0} : static_cast<std::uint8_t>(detail::numbered(line, "EXTI", 1, 15))};
}
consteval IpcChannel ipc(std::string_view name) {
  IpcChannel channel;
  if (name.empty() || name.size() > sizeof channel.name) static_cast<void>(detail::no_such_resource());
  for (std::size_t k = 0; k < name.size(); ++k) channel.name[k] = name[k];
  channel.size = static_cast<std::uint8_t>(name.size());
  return channel;
}

// The plant's names: "pwm:TIM1/3", "capture:TIM2/1", "spi:SPI5", "adc:ADC1/6", "exti:EXTI4", "ipc:app".
consteval ResourceName plant_name(PwmChannel pwm) {
  return ResourceName{}.append("pwm:TIM").append_number(pwm.timer).append("/").append_number(pwm.channel);
}
consteval ResourceName plant_name(CaptureChannel capture) {
  return ResourceName{}.append("capture:TIM").append_number(capture.timer).append("/").append_number(capture.channel);
}
consteval ResourceName plant_name(SpiBus spi) { return ResourceName{}.append("spi:SPI").append_number(spi.number); }
consteval ResourceName plant_name(AdcInput adc) {
  return ResourceName{}.append("adc:ADC").append_number(adc.adc).append("/").append_number(adc.channel);
}
consteval ResourceName plant_name(ExtiLine exti) { return ResourceName{}.append("exti:EXTI").append_number(exti.line); }
consteval ResourceName plant_name(IpcChannel ipc) { return ResourceName{}.append("ipc:").append(ipc.view()); }

}  // namespace duet::hardware
