// The bottom area's tabs (Problems, Block, Simulation, Generated, Live): one page shown at a time.
// `onShow(name)` lets the shell know, e.g. that a clicked wire should now plot rather than edit.
export function createBottomTabs(root, { onShow }) {
  const buttons = [...root.querySelectorAll('[data-bottom-tab]')];
  const pages = [...root.querySelectorAll('[data-bottom-page]')];
  let current = null;

  const show = (name) => {
    if (name === current) return;
    current = name;
    for (const page of pages) page.hidden = page.dataset.bottomPage !== name;
    for (const button of buttons) button.setAttribute('aria-selected', String(button.dataset.bottomTab === name));
    onShow(name);
  };
  for (const button of buttons) button.addEventListener('click', () => show(button.dataset.bottomTab));
  show('problems');
  return { show, get current() { return current; } };
}
