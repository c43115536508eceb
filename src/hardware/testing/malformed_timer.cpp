// A resource no STM32MP15 has (TIM18): must not compile, whatever the port.
#include "duet/hardware/resources.hpp"

constexpr auto malformed = duet::hardware::pwm("TIM18", 1);
