// The tab bar: one page shown at a time, chosen by the URL's #fragment so a page can be linked
// to (#scope) and the browser's back button moves between pages.
export function setUpTabs(pages, fallback) {
  const buttons = [...document.querySelectorAll('[data-tab]')];
  let current = null;

  const show = (name) => {
    if (!pages[name]) name = fallback;
    if (name === current) return;
    if (current) pages[current].hide();
    current = name;
    for (const section of document.querySelectorAll('.page')) section.hidden = section.dataset.page !== name;
    for (const button of buttons) button.setAttribute('aria-selected', String(button.dataset.tab === name));
    pages[name].show();
  };

  for (const button of buttons) {
    button.addEventListener('click', () => {
      if (location.hash !== `#${button.dataset.tab}`) location.hash = button.dataset.tab;
      else show(button.dataset.tab);
    });
  }
  window.addEventListener('hashchange', () => show(location.hash.slice(1)));
  show(location.hash.slice(1));
}
