// Line, area and bar charts on uPlot (web/vendor/uplot, copied from node_modules by the
// build): axes, ticks, the legend with its hover read-outs, drag-to-zoom (double-click
// resets) and resizing come from uPlot; this wrapper only maps the pages' options onto it.
import uPlot from '../vendor/uplot/uPlot.esm.min.js';
import { markFigure, toCSV } from './page.js';

const AXIS = { stroke: '#52606d', grid: { stroke: '#e4e7eb', width: 1 }, ticks: { stroke: '#cbd2d9', width: 1 } };

/**
 * A chart in `container` (a block element; the chart fills its width and follows it).
 *
 * Options:
 * - `x`, `y`: `{ label, range: [min, max] | (min, max) → [min, max] | null (auto), format(v) → text,
 *   ticks: number[] | null }` (`format` also formats the legend's read-out; `ticks` fixes
 *   the tick positions, `integer: true` keeps them on whole numbers);
 * - `series`: `[{ label, colour, width = 2, dash = [], fill = null, fillTo, bars = false,
 *   legend = true, value(v) → text, breaks: () → indices }]`, one per y column: `bars` draws
 *   bars centred on x, `fill` an area down to `fillTo` (a number, default the y minimum),
 *   `legend: false` leaves it out of the legend, `breaks` returns the indices k where the
 *   line must not join point k − 1 to point k;
 * - `height` (CSS px, default 300), `title`, and `overlay({ ctx, x, y, box, u })`, called
 *   after each redraw to draw labels and markers on the chart: `ctx` is set up in CSS pixels
 *   with the origin at the plot area's top left, `x(v)`, `y(v)` map data to it, `box` is the
 *   plot area `{ left: 0, top: 0, width, height }` and `u` the uPlot.
 * Series labels may hold HTML (<sub>); axis labels and CSV headers get its text.
 *
 * Returns `{ plot (the uPlot), update(data), csv(), canvas() }`: `data` is `[xs, ys1, ys2, …]`
 * (equal lengths, xs ascending, null for no value); `csv()` is the data as CSV with the
 * series labels as header; `canvas()` the chart's canvas (axes and series, not the legend).
 */
export function chart(container, { x = {}, y = {}, series, height = 300, overlay = null, title = '' }) {
  const fmtOf = (axis) => axis.format ?? ((v) => `${+v.toPrecision(6)}`);
  const text = (html) => html.replace(/<sub>(.*?)<\/sub>/g, '$1').replace(/<[^>]+>/g, '');
  const html = (h) => {
    const span = document.createElement('span');
    span.innerHTML = h;
    return span;
  };
  const range = (r) => (typeof r === 'function' ? (u, lo, hi) => r(lo, hi) : r ? () => r : undefined);
  const axis = (a, extra) => defined({
    ...AXIS, ...extra, label: a.label ? text(a.label) : undefined, values: (u, splits) => splits.map(fmtOf(a)),
    splits: a.ticks ? () => a.ticks : undefined, incrs: a.integer ? [1, 2, 5, 10, 20, 50, 100, 200, 500] : undefined,
  });
  const opts = {
    title,
    width: Math.max(container.clientWidth, 320),
    height,
    scales: { x: { time: false, range: range(x.range) }, y: { range: range(y.range) } },
    axes: [
      axis(x, {}),
      axis(y, { size: 56 }),
    ],
    series: [
      { label: x.label ? text(x.label) : 'x', value: (u, v) => (v === null || v === undefined ? '—' : fmtOf(x)(v)) },
      ...series.map((s) => defined({
        label: html(s.label),
        stroke: s.colour,
        width: s.width ?? 2,
        dash: s.dash ?? [],
        fill: s.fill ?? undefined,
        fillTo: s.fillTo,
        class: s.legend === false ? 'chart-no-legend' : undefined,
        points: { show: false },
        paths: s.bars ? uPlot.paths.bars({ size: [0.8, Infinity], align: 0 }) : undefined,
        value: (u, v) => (v === null || v === undefined ? '—' : (s.value ?? fmtOf(y))(v)),
        gaps: s.breaks ? breaksRefiner(s.breaks) : undefined,
      })),
    ],
    legend: { live: true },
    cursor: { points: { show: false } },
    hooks: {
      draw: [(u) => {
        if (overlay) {
          const dpr = uPlot.pxRatio;
          const { ctx } = u;
          ctx.save();
          ctx.setTransform(dpr, 0, 0, dpr, u.bbox.left, u.bbox.top);
          const box = { left: 0, top: 0, width: u.bbox.width / dpr, height: u.bbox.height / dpr };
          overlay({ ctx, x: (v) => u.valToPos(v, 'x'), y: (v) => u.valToPos(v, 'y'), box, u });
          ctx.restore();
        }
        // The first figure is the first chart drawn with data, not an empty frame.
        if (u.data[0]?.length) markFigure();
      }],
    },
  };
  let data = [[], ...series.map(() => [])];
  const plot = new uPlot(opts, data, container);
  new ResizeObserver(() => {
    const w = Math.max(container.clientWidth, 320);
    if (w !== plot.width) plot.setSize({ width: w, height });
  }).observe(container);
  return {
    plot,
    update(next) {
      data = next;
      plot.batch(() => plot.setData(next)); // drawn now, not in a microtask: the page times it
    },
    csv() {
      const header = [opts.series[0].label, ...series.map((s) => text(s.label))];
      return toCSV(header, data[0].map((_, i) => data.map((col) => col[i])));
    },
    canvas: () => plot.ctx.canvas,
  };
}

/** The object without its undefined entries (uPlot takes a present key as an override). */
const defined = (o) => Object.fromEntries(Object.entries(o).filter(([, v]) => v !== undefined));

/** A uPlot gaps refiner that breaks the line between points k − 1 and k for each k given. */
function breaksRefiner(breaks) {
  return (u, seriesIdx, idx0, idx1, gaps) => {
    const xs = u.data[0];
    const out = [...gaps];
    for (const k of breaks()) {
      if (k <= idx0 || k > idx1) continue;
      uPlot.addGap(out, Math.round(u.valToPos(xs[k - 1], 'x', true)) + 1, Math.round(u.valToPos(xs[k], 'x', true)));
    }
    return out.sort((a, b) => a[0] - b[0]);
  };
}

/**
 * For an overlay: a dashed vertical line at x = v across the plot area, with `text` at its
 * top (to the `align` side of it), in `colour`; `line: false` writes the text alone.
 */
export function markX({ ctx, x, box }, v, { colour = '#52606d', text = '', align = 'left', dash = [4, 3], width = 1.2, line = true } = {}) {
  ctx.strokeStyle = line ? colour : 'transparent';
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.beginPath();
  ctx.moveTo(x(v), 0);
  ctx.lineTo(x(v), box.height);
  ctx.stroke();
  ctx.setLineDash([]);
  if (!text) return;
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = align;
  ctx.lineJoin = 'round';
  ctx.lineWidth = 3.5;
  ctx.strokeStyle = 'rgba(255,255,255,0.92)';
  const px = x(v) + (align === 'left' ? 4 : -4);
  ctx.strokeText(text, px, 3);
  ctx.fillStyle = colour;
  ctx.fillText(text, px, 3);
}
