// Timing of a page's redraws, its badge, and the marks the page tests read
// (window.fisstTiming: { page, firstFigure, ready, last, history }).

const HISTORY = 1000;
const record = (window.fisstTiming ??= { page: null, firstFigure: null, ready: null, last: {}, history: {} });

/** Called by the figure modules after each draw: the first call marks the first figure. */
export function markFigure() {
  if (record.firstFigure !== null) return;
  record.firstFigure = performance.now();
  performance.mark('fisst:first-figure');
}

/** Marks the page as ready for the tests (body[data-ready]) once its figures are drawn. */
export function pageReady() {
  record.ready = performance.now();
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
