// Text widths without a DOM, for sizing blocks and labels before layout (ELK needs the sizes up
// front). An estimate per character class of a sans-serif font; it errs wide, so text fits.
const narrow = new Set([...'ijlt.,:;!|\'()[]{} fr1']);
const wide = new Set([...'mwMW@%']);

export function textWidth(text, fontSize) {
  let units = 0;
  for (const character of String(text)) {
    if (narrow.has(character)) units += 0.36;
    else if (wide.has(character)) units += 0.9;
    else if (character >= 'A' && character <= 'Z') units += 0.7;
    else units += 0.58;
  }
  return Math.ceil(units * fontSize);
}
