// Generated code that uses a PWM channel the robot's board does not route: must not compile.
#include "duet/hardware/hardware.hpp"

constexpr auto unrouted = duet::hardware::pwm("TIM1", 1);
void step() { duet::hardware::pwm_write<unrouted>(50.0F); }
