// The WebSocket is on the page's own host and port (the back ends serve both), unless the page
// was opened with ?ws=ws://host:port/ — handy when the files come from elsewhere (the mock, a
// file server) but the data from a real back end.
export function websocketUrl(location) {
  const override = new URLSearchParams(location.search).get('ws');
  if (override) return override;
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/`;
}
