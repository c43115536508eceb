// The mock target: a balancing robot's worth of signals and parameters, computed from the time so
// that any sample can be produced on demand and the plots show something recognisable.

export const description = {
  type: 'description',
  application: 'mockbot',
  backend: 'monitor',
  telemetry_period_us: 1000,
  telemetry: [
    { name: 'theta', unit: 'deg', type: 'float32', min: -90, max: 90 },
    { name: 'theta_reference', unit: 'deg', type: 'float32', min: -90, max: 90 },
    { name: 'rate', unit: 'deg/s', type: 'float32', min: -500, max: 500 },
    { name: 'wheel_left', unit: 'rad/s', type: 'float32', min: -50, max: 50 },
    { name: 'wheel_right', unit: 'rad/s', type: 'float32', min: -50, max: 50 },
    { name: 'motor_left', unit: '%', type: 'int16', min: -100, max: 100 },
    { name: 'motor_right', unit: '%', type: 'int16', min: -100, max: 100 },
    { name: 'battery', unit: 'V', type: 'float32', min: 0, max: 12.6 },
    { name: 'distance', unit: 'cm', type: 'uint16', min: 0, max: 400 },
    // The wall-clock time (ms since the Unix epoch) at which the sample was taken: lets a
    // benchmark measure the latency from target to page.
    { name: 'wall_clock', unit: 'ms', type: 'float64', min: 0, max: 1e14 },
  ],
  parameters: [
    { name: 'P', unit: '', type: 'float32', min: 0, max: 1 },
    { name: 'I', unit: '', type: 'float32', min: 0, max: 1 },
    { name: 'D', unit: '', type: 'float32', min: 0, max: 1 },
    {
      name: 'mode',
      unit: '',
      type: 'uint8',
      min: 0,
      max: 3,
      labels: ['off', 'slow', 'normal', 'fast'].map((text, value) => ({ value, text })),
    },
  ],
};

export function initialParameters() {
  return { P: Math.fround(0.0196), I: 0, D: Math.fround(0.0187), mode: 1 };
}

// Every signal's value at time `t` seconds; `wallMs` is when that sample was taken.
export function sampleAt(t, parameters, wallMs) {
  const gain = 1 + 4 * parameters.P;
  const theta = 6 * gain * Math.sin(2 * Math.PI * 0.5 * t) + 0.8 * Math.sin(2 * Math.PI * 7 * t);
  const reference = 4 * Math.sign(Math.sin(2 * Math.PI * 0.2 * t));
  const rate = 6 * gain * Math.PI * Math.cos(2 * Math.PI * 0.5 * t); // theta's slope
  const wheel = 12 * Math.sin(2 * Math.PI * 0.3 * t);
  // A short spike every 3 s, to show that the scope's decimation keeps spikes.
  const spike = t % 3 < 0.001 ? 20 : 0;
  const motor = Math.round(Math.max(-100, Math.min(100, 60 * Math.sin(2 * Math.PI * 0.5 * t + 0.4) + spike)));
  return [
    Math.fround(theta),
    reference,
    Math.fround(rate),
    Math.fround(wheel + 0.3 * Math.sin(2 * Math.PI * 11 * t)),
    Math.fround(wheel - 0.3 * Math.sin(2 * Math.PI * 13 * t)),
    motor,
    -motor,
    Math.fround(7.4 - 0.02 * Math.sin(2 * Math.PI * 0.05 * t) - 0.001 * (t % 60)),
    Math.round(120 + 80 * Math.sin(2 * Math.PI * 0.1 * t)),
    wallMs,
  ];
}
