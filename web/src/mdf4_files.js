// "Save as MDF4": the back end writes the file with duet's MDF 4 writer (src/mdf4) and the page offers what it
// answers as a download. The recorder's capture lives in the back end (GET); the Scope's samples live here, so
// the page posts them (POST, JSON). Back ends that write no MDF4 (the mock) leave `mdf4` out of their
// description, and the buttons stay hidden.

// The back end's HTTP address of `path`: the WebSocket's host and port, which may differ from the page's (?ws=).
export function backendHttpUrl(websocketUrl, path) {
  const url = new URL(path, websocketUrl);
  url.protocol = url.protocol === 'wss:' ? 'https:' : 'http:';
  return url.href;
}

// The Scope's request: the times, then each signal shown with its unit and values, a gap (NaN) as null.
export function scopeRequest(time, signals) {
  return {
    time_s: Array.from(time),
    signals: signals.map(({ name, unit, values }) => ({
      name,
      unit: unit ?? '',
      values: Array.from(values, (value) => (Number.isFinite(value) ? value : null)),
    })),
  };
}

// The name the back end gave in Content-Disposition, else `fallback`.
export function attachmentName(disposition, fallback) {
  const match = /filename="([^"]+)"/.exec(disposition ?? '');
  return match ? match[1] : fallback;
}

// `offer` is the description's `mdf4` ({recorder, scope, max_request_bytes}); `fetchFile` is fetch, `save(name,
// blob)` offers the download. Each call resolves to {ok, message} for the page to show.
export function createMdf4Files({ websocketUrl, fetchFile, save }) {
  let offer = null;

  async function download(path, init, fallbackName) {
    let response;
    try {
      response = await fetchFile(backendHttpUrl(websocketUrl, path), init);
    } catch (error) {
      return { ok: false, message: `MDF4: the back end did not answer (${error.message})` };
    }
    if (!response.ok) return { ok: false, message: `MDF4: ${(await response.text()).trim() || response.status}` };
    const blob = await response.blob();
    const name = attachmentName(response.headers.get('Content-Disposition'), fallbackName);
    save(name, blob);
    return { ok: true, message: `saved ${name} (${Math.ceil(blob.size / 1024)} KB)` };
  }

  return {
    describe(description) {
      offer = description?.mdf4 ?? null;
    },
    get available() {
      return offer !== null;
    },
    recorder() {
      if (!offer) return Promise.resolve({ ok: false, message: 'this back end writes no MDF4' });
      return download(offer.recorder, { method: 'GET' }, 'capture.mf4');
    },
    scope(time, signals) {
      if (!offer) return Promise.resolve({ ok: false, message: 'this back end writes no MDF4' });
      const body = JSON.stringify(scopeRequest(time, signals));
      const bytes = new Blob([body]).size;
      if (offer.max_request_bytes && bytes > offer.max_request_bytes) {
        const megabytes = (value) => (value / 1048576).toFixed(1);
        return Promise.resolve({
          ok: false,
          message: `MDF4: the samples are ${megabytes(bytes)} MB as JSON, more than the back end takes (${megabytes(offer.max_request_bytes)} MB): choose fewer signals`,
        });
      }
      return download(offer.scope, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body }, 'scope.mf4');
    },
  };
}
