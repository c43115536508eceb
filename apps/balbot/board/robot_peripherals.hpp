#pragma once
// The robot's peripherals on the STM32MP15 (thesis tables 5.3-5.7, docs/BOARD.md's pin map): what the model's
// hardware blocks reach (robot_peripherals.cpp routes its resources to the drivers), and what each interrupt
// task's handler clears before the model runs.

namespace balbot::board {

// Clocks, pins, timers, the IMU's SPI with its DMA streams, the battery's ADC, the IMU's EXTI line, and the outputs'
// safe state (motor driver in standby, PWM off) for the fault handlers and Linux's shutdown. False, with the
// outputs safe, if a peripheral refused its set-up. Call before enabling interrupts.
bool start_peripherals();

// The interrupt tasks' handlers, before the model's task: each clears its peripheral's flag and keeps what the
// model reads. False: the interrupt was not the model's event (a stale or foreign flag), and the task should not run.
bool on_pwm_period();       // TIM1_CC: the once-per-period compare on channel 1
bool on_left_hall();        // TIM2: a capture on channel 1
bool on_right_hall();       // TIM4: a capture on channel 4
bool on_echo_edge();        // TIM5: a capture on channel 2, either edge
bool on_imu_data_ready();   // EXTI8
bool on_spi_transmitted();  // DMA2 stream 3
bool on_spi_received();     // DMA2 stream 2
void on_spi_error();        // SPI5: an overrun or a mode fault stopped the transfer (no model task)
bool on_adc_samples();      // DMA2 stream 4

}  // namespace balbot::board
