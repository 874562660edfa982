// Every setting of a page in its URL (?name=value&…), so that a view can be shared and
// reloaded. Only the settings that differ from their defaults are written.

const encode = (v) => {
  if (typeof v === 'number' || typeof v === 'string') return String(v);
  if (typeof v === 'boolean') return v ? '1' : '0';
  return JSON.stringify(v);
};

function decode(raw, fallback, check) {
  if (raw === null) return structuredClone(fallback);
  let v;
  if (typeof fallback === 'number') v = raw.trim() === '' ? NaN : Number(raw);
  else if (typeof fallback === 'boolean') v = raw === '1' || raw === 'true';
  else if (typeof fallback === 'string') v = raw;
  else {
    try {
      v = JSON.parse(raw);
    } catch {
      return structuredClone(fallback);
    }
  }
  if (typeof fallback === 'number' && !Number.isFinite(v)) return fallback;
  if (check && !check(v)) return structuredClone(fallback);
  return v;
}

/**
 * The page's settings: `defaults` (name → value; numbers, strings, booleans, or JSON values
 * such as arrays of components) overlaid with what the URL says. A URL value of the wrong
 * type, or one that `check[name](value)` rejects, falls back to the default (no error: a
 * hand-edited URL must not break the page). Returns `{ values, save(), write() }`: change
 * `values` and call `save()` (the URL is rewritten 150 ms after the last call, with
 * history.replaceState, so a drag does not flood the history) or `write()` (at once).
 */
export function urlState(defaults, { check = {} } = {}) {
  const params = new URLSearchParams(location.search);
  const values = {};
  for (const [name, fallback] of Object.entries(defaults)) values[name] = decode(params.get(name), fallback, check[name]);
  let timer = null;
  const write = () => {
    clearTimeout(timer);
    timer = null;
    const out = new URLSearchParams();
    for (const [name, fallback] of Object.entries(defaults)) {
      const v = encode(values[name]);
      if (v !== encode(fallback)) out.set(name, v);
    }
    const search = out.toString();
    const url = `${location.pathname}${search ? `?${search}` : ''}${location.hash}`;
    if (url !== `${location.pathname}${location.search}${location.hash}`) history.replaceState(null, '', url);
  };
  return {
    values,
    write,
    save() {
      clearTimeout(timer);
      timer = setTimeout(write, 150);
    },
  };
}
