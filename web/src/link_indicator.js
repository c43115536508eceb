// The dot in the top bar: green when connected, amber while connecting, red while waiting to
// retry (with the time until the next attempt), and a note when the target itself went away.
export function createLinkIndicator(node) {
  const text = node.querySelector('.link-text');
  let targetAway = false;
  let state = { name: 'connecting' };

  const render = () => {
    let name = state.name;
    let words = { connecting: 'connecting…', connected: 'connected', waiting: 'disconnected' }[name] ?? name;
    if (name === 'waiting' && state.retryInMs) words = `disconnected, retry in ${Math.round(state.retryInMs / 1000) || 1} s`;
    if (name === 'connected' && targetAway) {
      name = 'target-away';
      words = 'target away';
    }
    node.dataset.state = name;
    text.textContent = words;
    node.title = `${words} — ${state.url ?? ''}`;
  };

  return {
    socket(next) {
      state = next;
      if (next.name !== 'connected') targetAway = false;
      render();
    },
    channel(open) {
      targetAway = !open;
      render();
    },
  };
}
