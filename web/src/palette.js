// Line colours that stay apart from each other on a white background, also for the common
// colour-vision deficiencies (after Okabe & Ito, extended with darker tones).
const colours = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#7f3c8d', '#8c6d31', '#000000', '#b22222', '#2f4f4f', '#6b8e23'];

export function colourFor(index) {
  return colours[index % colours.length];
}
