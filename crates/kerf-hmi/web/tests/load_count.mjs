// The load test's clients: `n` WebSockets on `url`'s stream for `secs`
// seconds, each counting its states (every one parsed, ACTIVE, machine
// time never going back). Self-contained (no imports, no closures over
// this module), so it runs as it is in a browser page (load.mjs passes it
// to the page) and in node (load_clients.mjs).

/** Resolves to one {states, error} per client. */
export async function countStates({ url, n, secs }) {
  const one = () => new Promise((res) => {
    const ws = new WebSocket(url);
    const c = { states: 0, error: null, tLast: 0 };
    ws.onmessage = (ev) => {
      if (typeof ev.data !== 'string') return;
      try {
        const s = JSON.parse(ev.data);
        if (s.execution !== 'ACTIVE') throw new Error(`not ACTIVE: ${s.execution}`);
        if (s.t < c.tLast) throw new Error(`machine time went back: ${c.tLast} → ${s.t}`);
        c.tLast = s.t;
        c.states++;
      } catch (e) { c.error ||= String(e); }
    };
    ws.onerror = () => { c.error ||= 'socket error'; };
    ws.onclose = () => { c.error ||= 'closed'; };
    setTimeout(() => { ws.onclose = null; ws.close(); res({ states: c.states, error: c.error }); }, secs * 1000);
  });
  return Promise.all(Array.from({ length: n }, one));
}
