// A page's plumbing: number formats, controls with live read-outs, settings in the URL,
// PNG/CSV downloads, redraw timing and the marks the page tests read. Nothing here touches
// the DOM when imported (the page tests import the formats in Node).

// ---------------------------------------------------------------- number formats
// Number formatting for read-outs (no DOM: the page tests import it in Node too).

/** Formats a number compactly: `digits` decimals, exponent form below 1e-3 and from 1e5. */
export function fmt(x, digits = 4) {
  if (x === null || x === undefined) return '—';
  if (!Number.isFinite(x)) return String(x);
  if (x !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e5)) return x.toExponential(digits - 1);
  return Number(x.toFixed(digits)).toString();
}

/** A duration in milliseconds, or '—' when there is none yet. */
export const msText = (ms) => (ms === null || ms === undefined ? '—' : `${ms.toFixed(1)} ms`);

/** A 2D point as `(x, y)` with `digits` decimals. */
export const pointText = (a, digits = 3) => `(${a[0].toFixed(digits)}, ${a[1].toFixed(digits)})`;

/** Median of an array of numbers (the upper one of an even count); null when empty. */
export function median(values) {
  if (values.length === 0) return null;
  return [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
}

// ---------------------------------------------------------------- controls
// Controls with live read-outs: sliders, button groups, selects, a progress bar.

/** The element with this id. */
export const $ = (id) => document.getElementById(id);

/**
 * Binds the range input `id` and its read-out `<output id="<id>-out">` (if any): sets the
 * input to `value` (the browser clamps it to min/max and snaps it to the step), shows
 * `format(v)` in the read-out and calls `onInput(v)` on every move. `parse` turns the
 * input's text into the value (default Number). Returns `{ input, value, set(v) }`; `set`
 * moves the slider without calling onInput and returns the value it took.
 */
export function slider(id, { value, format = String, onInput = null, parse = Number }) {
  const input = $(id);
  const output = $(`${id}-out`);
  if (value !== undefined && value !== null) input.value = String(value);
  const read = () => {
    const v = parse(input.value);
    if (output) output.value = format(v);
    return v;
  };
  if (onInput) input.addEventListener('input', () => onInput(read()));
  read();
  return {
    input,
    get value() { return parse(input.value); },
    set(v) {
      input.value = String(v);
      return read();
    },
  };
}

/**
 * A group of toggle buttons with ids `<prefix>-<value>` for each of `values`: the pressed
 * one has aria-pressed="true". `onChange(value)` is called on a click. Returns
 * `{ value, set(v) }` (`set` does not call onChange; an unknown value selects the first).
 */
export function choice(prefix, values, { value, onChange = null }) {
  let current = null;
  const set = (v) => {
    current = values.includes(v) ? v : values[0];
    for (const w of values) $(`${prefix}-${w}`).setAttribute('aria-pressed', String(w === current));
    return current;
  };
  for (const w of values) {
    $(`${prefix}-${w}`).addEventListener('click', () => {
      set(w);
      onChange?.(w);
    });
  }
  set(value);
  return { get value() { return current; }, set };
}

/** Binds the select `id`: `{ value, set(v) }`, `onChange(value)` on a change. */
export function select(id, { value, onChange = null }) {
  const el = $(id);
  if (value !== undefined && [...el.options].some((o) => o.value === value)) el.value = value;
  if (onChange) el.addEventListener('input', () => onChange(el.value));
  return { get value() { return el.value; }, set(v) { el.value = v; return el.value; } };
}

/**
 * A progress bar appended to `container` (a <progress> and a text read-out):
 * `set(fraction, text)`, `done(text)`; `element` is the wrapper.
 */
export function progressBar(container, { label = 'progress' } = {}) {
  const el = document.createElement('span');
  el.className = 'progress';
  el.innerHTML = `<progress max="1" value="0" aria-label="${label}"></progress> <output></output>`;
  container.append(el);
  const bar = el.querySelector('progress');
  const out = el.querySelector('output');
  return {
    element: el,
    set(fraction, text = `${Math.round(100 * fraction)} %`) {
      bar.value = Math.min(Math.max(fraction, 0), 1);
      out.value = text;
    },
    done(text = 'done') {
      bar.value = 1;
      out.value = text;
    },
  };
}

// ---------------------------------------------------------------- URL state
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

// ---------------------------------------------------------------- downloads
// "Download PNG / CSV" controls for figures.

/** CSV text from a header and rows of values (numbers at full precision; null → empty). */
export function toCSV(header, rows) {
  const cell = (v) => {
    if (v === null || v === undefined) return '';
    const s = typeof v === 'number' ? String(v) : String(v);
    return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
  };
  return [header, ...rows].map((r) => r.map(cell).join(',')).join('\n') + '\n';
}

function save(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** A copy of a canvas's bitmap on white (the page's canvases are transparent). */
export function onWhite(canvas) {
  const out = document.createElement('canvas');
  out.width = canvas.width;
  out.height = canvas.height;
  const ctx = out.getContext('2d');
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.drawImage(canvas, 0, 0);
  return out;
}

/**
 * Adds "PNG" and "CSV" buttons to `parent` (a figure or its caption): `png()` returns the
 * canvas to save, `csv()` the CSV text; files are named `<name>.png` / `<name>.csv` (`name`
 * may be a function, for names that follow the page's settings). Either may be left out. The buttons carry data-download="png" / "csv".
 */
export function downloads(parent, { name, png = null, csv = null }) {
  const nameOf = () => (typeof name === 'function' ? name() : name);
  const bar = document.createElement('span');
  bar.className = 'downloads';
  const button = (kind, label, act) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.dataset.download = kind;
    b.textContent = label;
    b.title = `download the figure as ${kind.toUpperCase()}`;
    b.addEventListener('click', act);
    bar.append(b);
  };
  if (png) button('png', 'PNG', () => onWhite(png()).toBlob((blob) => save(blob, `${nameOf()}.png`), 'image/png'));
  if (csv) button('csv', 'CSV', () => save(new Blob([csv()], { type: 'text/csv' }), `${nameOf()}.csv`));
  parent.append(bar);
  return bar;
}

// ---------------------------------------------------------------- timing
// Timing of a page's redraws, its badge, and the marks the page tests read
// (window.fisstTiming: { page, firstFigure, ready, last, history }).

const HISTORY = 1000;
const timingRecord = () => (window.fisstTiming ??= { page: null, firstFigure: null, ready: null, last: {}, history: {} });

/** Called by the figure modules after each draw: the first call marks the first figure. */
export function markFigure() {
  const record = timingRecord();
  if (record.firstFigure !== null) return;
  record.firstFigure = performance.now();
  performance.mark('fisst:first-figure');
}

/**
 * Resolves after the browser has painted what is drawn so far: `await nextFrame()` between a
 * page's first figure and the rest shows that figure at once instead of after all of them.
 */
export const nextFrame = () => new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));

/** Marks the page as ready for the tests (body[data-ready]) once its figures are drawn. */
export function pageReady() {
  timingRecord().ready = performance.now();
  performance.mark('fisst:ready');
  document.body.dataset.ready = 'true';
}

/**
 * Timings of the page `page` by panel: `time(panel, f)` runs f and records its duration in
 * ms (the last and up to 1000 past ones), `record(panel, ms)` records one measured
 * elsewhere, `last[panel]`, `history[panel]`. `badge(element, labels)` fills the element
 * with "last redraw: <label> <ms> · …" for the panels in `labels` (an object panel → label;
 * each time is a span with id `redraw-<panel>`), refreshed by `show()`.
 */
export function timings(page) {
  const record = timingRecord();
  record.page = page;
  let shown = null;
  const add = (panel, ms) => {
    record.last[panel] = ms;
    const h = (record.history[panel] ??= []);
    h.push(ms);
    if (h.length > HISTORY) h.shift();
    return ms;
  };
  return {
    last: record.last,
    history: record.history,
    record: add,
    time(panel, f) {
      const t0 = performance.now();
      const out = f();
      add(panel, performance.now() - t0);
      return out;
    },
    badge(element, labels) {
      element.classList.add('timing-badge');
      element.textContent = 'last redraw: ';
      Object.entries(labels).forEach(([panel, label], k) => {
        if (k > 0) element.append(' · ');
        const span = document.createElement('span');
        span.id = `redraw-${panel}`;
        span.textContent = '—';
        element.append(`${label} `, span);
      });
      shown = labels;
    },
    show() {
      if (!shown) return;
      for (const panel of Object.keys(shown)) {
        const ms = record.last[panel];
        document.getElementById(`redraw-${panel}`).textContent = ms === undefined ? '—' : `${ms.toFixed(1)} ms`;
      }
    },
  };
}
