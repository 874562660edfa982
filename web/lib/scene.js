// Scene views: what the pages draw on canvas and let the user drag — HiDPI canvas set-up,
// linear scales and axes, drawing primitives, the view in data coordinates with dragging,
// panning and zooming, and a threshold gauge.
import { markFigure } from './page.js';

// ---------------------------------------------------------------- canvas set-up, scales, axes
// Canvas set-up for HiDPI screens, linear scales and axes for the scene views.

/** Sizes a canvas for the device pixel ratio; returns its 2D context in CSS pixels. */
export function setupCanvas(canvas, width, height) {
  const dpr = window.devicePixelRatio || 1;
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  canvas.width = Math.round(width * dpr);
  canvas.height = Math.round(height * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return ctx;
}

/** A linear map from [d0, d1] to [p0, p1], with `.invert`. */
export function scale(d0, d1, p0, p1) {
  const f = (x) => p0 + ((x - d0) / (d1 - d0)) * (p1 - p0);
  f.invert = (p) => d0 + ((p - p0) / (p1 - p0)) * (d1 - d0);
  return f;
}

/** Evenly spaced ticks from a to b inclusive (n intervals). */
export function ticks(a, b, n) {
  return Array.from({ length: n + 1 }, (_, i) => a + ((b - a) * i) / n);
}

/** Round ticks covering [a, b]: steps of 1, 2 or 5 × 10^k, about `n` of them. */
export function niceTicks(a, b, n = 6) {
  const raw = (b - a) / Math.max(n, 1);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw * (1 - 1e-9));
  const out = [];
  for (let t = Math.ceil(a / step - 1e-9) * step; t <= b + 1e-9 * step; t += step) out.push(Math.abs(t) < 1e-12 * step ? 0 : t);
  return out;
}

/** Axes with ticks and labels inside a plot box { left, top, width, height }. */
export function drawAxes(ctx, box, x, y, { xTicks, yTicks, xLabel, yLabel, fmt = (v) => `${v}` }) {
  ctx.save();
  ctx.strokeStyle = '#52606d';
  ctx.fillStyle = '#52606d';
  ctx.lineWidth = 1;
  ctx.font = '11px system-ui, sans-serif';
  ctx.beginPath();
  ctx.moveTo(box.left, box.top);
  ctx.lineTo(box.left, box.top + box.height);
  ctx.lineTo(box.left + box.width, box.top + box.height);
  ctx.stroke();
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  for (const t of xTicks) {
    const px = x(t);
    ctx.beginPath();
    ctx.moveTo(px, box.top + box.height);
    ctx.lineTo(px, box.top + box.height + 4);
    ctx.stroke();
    ctx.fillText(fmt(t), px, box.top + box.height + 6);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const t of yTicks) {
    const py = y(t);
    ctx.beginPath();
    ctx.moveTo(box.left - 4, py);
    ctx.lineTo(box.left, py);
    ctx.stroke();
    ctx.fillText(fmt(t), box.left - 6, py);
  }
  ctx.font = '12px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  if (xLabel) ctx.fillText(xLabel, box.left + box.width / 2, box.top + box.height + 34);
  if (yLabel) {
    ctx.translate(box.left - 30, box.top + box.height / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText(yLabel, 0, 0);
  }
  ctx.restore();
}

// ---------------------------------------------------------------- drawing primitives
// Drawing primitives for the scene views (pixel coordinates; a view's px/py map data to them).

/**
 * Adds the k-σ ellipse of a Gaussian's position block (`cov[0][0]`, `cov[0][1]`, `cov[1][1]`;
 * longer states are fine) centred on `mean` to the current path, in the pixel space of the
 * linear scales `x`, `y`: the unit circle mapped through the Cholesky factor of the block.
 * Call `ctx.beginPath()` first and stroke/fill afterwards (many ellipses can share a path).
 */
export function ellipsePath(ctx, x, y, mean, cov, k = 1) {
  const l11 = Math.sqrt(Math.max(cov[0][0], 0));
  const l21 = l11 > 0 ? cov[0][1] / l11 : 0;
  const l22 = Math.sqrt(Math.max(cov[1][1] - l21 * l21, 0));
  const sx = x(1) - x(0);
  const sy = y(1) - y(0);
  ctx.save();
  // x' = a u + c v + e, y' = b u + d v + f for the unit circle (u, v).
  ctx.transform(sx * k * l11, sy * k * l21, 0, sy * k * l22, x(mean[0]), y(mean[1]));
  ctx.moveTo(1, 0);
  ctx.arc(0, 0, 1, 0, 2 * Math.PI);
  ctx.restore();
}

/** A five-pointed star path of outer radius r at (px, py); fill or stroke it after. */
export function starPath(ctx, px, py, r) {
  ctx.beginPath();
  for (let k = 0; k < 10; k++) {
    const a = -Math.PI / 2 + (k * Math.PI) / 5;
    const rr = k % 2 === 0 ? r : r * 0.45;
    ctx.lineTo(px + rr * Math.cos(a), py + rr * Math.sin(a));
  }
  ctx.closePath();
}

/** Strokes a ✕ (`diagonal`) or ✚ of half-size r at (px, py) in the current stroke style. */
export function cross(ctx, px, py, r, diagonal = true) {
  ctx.beginPath();
  if (diagonal) {
    ctx.moveTo(px - r, py - r);
    ctx.lineTo(px + r, py + r);
    ctx.moveTo(px + r, py - r);
    ctx.lineTo(px - r, py + r);
  } else {
    ctx.moveTo(px - r, py);
    ctx.lineTo(px + r, py);
    ctx.moveTo(px, py - r);
    ctx.lineTo(px, py + r);
  }
  ctx.stroke();
}

/** A filled circle of radius r at (px, py) with an optional outline. */
export function dot(ctx, px, py, r, fill, stroke = null, lineWidth = 1) {
  ctx.beginPath();
  ctx.arc(px, py, r, 0, 2 * Math.PI);
  ctx.fillStyle = fill;
  ctx.fill();
  if (stroke) {
    ctx.strokeStyle = stroke;
    ctx.lineWidth = lineWidth;
    ctx.stroke();
  }
}

/** Text with a white halo so that it reads over lines and heat maps. */
export function haloText(ctx, text, px, py, colour) {
  ctx.save();
  ctx.lineJoin = 'round';
  ctx.lineWidth = 3.5;
  ctx.strokeStyle = 'rgba(255,255,255,0.92)';
  ctx.strokeText(text, px, py);
  ctx.fillStyle = colour;
  ctx.fillText(text, px, py);
  ctx.restore();
}

/** Restricts drawing to the box { left, top, width, height } (inside a save/restore). */
export function clipTo(ctx, box) {
  ctx.beginPath();
  ctx.rect(box.left, box.top, box.width, box.height);
  ctx.clip();
}

/**
 * Text with subscripts at (px, py), baseline bottom: `parts` like [['c'], ['M', 'sub'],
 * ['/c'], ['A', 'sub'], [' = 0.25']]; `align` 'left' or 'right' of px. Returns the width.
 */
export function richText(ctx, parts, px, py, colour, align = 'left') {
  const base = ctx.font;
  const small = base.replace(/(\d+)px/, (_, n) => `${Math.round(Number(n) * 0.78)}px`);
  const widthOf = ([t, sub]) => {
    ctx.font = sub ? small : base;
    return ctx.measureText(t).width;
  };
  const total = parts.reduce((w, p) => w + widthOf(p), 0);
  let x = align === 'right' ? px - total : px;
  ctx.save();
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  for (const part of parts) {
    const w = widthOf(part);
    haloText(ctx, part[0], x, py + (part[1] ? 3 : 0), colour);
    x += w;
  }
  ctx.restore();
  ctx.font = base;
  return total;
}

/** Width of `richText`'s parts in the current font. */
export function richTextWidth(ctx, parts) {
  const base = ctx.font;
  const small = base.replace(/(\d+)px/, (_, n) => `${Math.round(Number(n) * 0.78)}px`);
  let w = 0;
  for (const [t, sub] of parts) {
    ctx.font = sub ? small : base;
    w += ctx.measureText(t).width;
  }
  ctx.font = base;
  return w;
}

/**
 * Places labels without overlap: `place(left, bottom, w, h)` tries the rectangle and the
 * same shifted by ±12, ±24 px inside `box`; returns the shift used, or null (then skip the
 * label). Labels placed first win.
 */
export function labelPlacer(box) {
  const placed = [];
  return (left, bottom, w, h) => {
    for (const dy of [0, -12, 12, -24, 24]) {
      const r = { l: left, t: bottom + dy - h, r: left + w, b: bottom + dy };
      if (r.t < box.top || r.b > box.top + box.height) continue;
      if (placed.every((o) => r.l >= o.r || r.r <= o.l || r.t >= o.b || r.b <= o.t)) {
        placed.push(r);
        return dy;
      }
    }
    return null;
  };
}

/**
 * Draws a Gaussian mixture's components (`{ weight, mean, cov }`, position in the first two
 * coordinates) as k-σ ellipses, more opaque the heavier they are (three classes of weight
 * relative to the heaviest), and their means as dots (`dots`); `colourOf(i)` colours
 * component i. One path per colour and class, so thousands of components stay cheap.
 */
export function drawMixture(ctx, px, py, mixture, { colourOf = () => '#0072b2', k = 1, dots = true, lineWidth = 1.2 } = {}) {
  const wmax = mixture.reduce((a, c) => Math.max(a, c.weight), 0);
  const groups = new Map(); // colour → [light, medium, heavy] index lists
  mixture.forEach((c, i) => {
    const colour = colourOf(i);
    if (!groups.has(colour)) groups.set(colour, [[], [], []]);
    const t = wmax > 0 ? c.weight / wmax : 1;
    groups.get(colour)[t < 0.05 ? 0 : t < 0.3 ? 1 : 2].push(i);
  });
  ctx.save();
  ctx.lineWidth = lineWidth;
  for (const [colour, classes] of groups) {
    ctx.strokeStyle = colour;
    ctx.fillStyle = colour;
    classes.forEach((members, j) => {
      if (members.length === 0) return;
      ctx.globalAlpha = [0.3, 0.55, 0.9][j];
      ctx.beginPath();
      for (const i of members) ellipsePath(ctx, px, py, mixture[i].mean, mixture[i].cov, k);
      ctx.stroke();
    });
    if (!dots) continue;
    ctx.globalAlpha = 1;
    ctx.beginPath();
    for (const i of classes.flat()) {
      const [x, y] = [px(mixture[i].mean[0]), py(mixture[i].mean[1])];
      ctx.moveTo(x + 1.6, y);
      ctx.arc(x, y, 1.6, 0, 2 * Math.PI);
    }
    ctx.fill();
  }
  ctx.restore();
}

// ---------------------------------------------------------------- the scene view
// A scene view: a HiDPI canvas showing a rectangle of data coordinates, with dragging of the
// page's objects, and (opt-in) panning and zooming, all in data coordinates.

/**
 * Makes `canvas` a view of the data rectangle x × y drawn in `box` (CSS pixels inside the
 * canvas of `width` × `height`).
 *
 * Options: `draw(ctx, view)` paints the scene (called by `view.redraw()` after a clear);
 * `drag` = `{ hit(point, event) → target | null, start?(target, point), move(target, { point,
 * start, delta }), end?(target) }` makes objects draggable (mouse, pen and touch; `point`,
 * `start` and `delta` in data coordinates; the page redraws in `move`); `pan` lets a drag on
 * empty space move the view, `zoom` lets Ctrl/⌘ + wheel (or a trackpad pinch) zoom about the
 * pointer; a double-click restores the initial rectangle. `onView(view)` hears of every
 * pan or zoom (the view has already redrawn).
 *
 * The view: `px(x)`, `py(y)` (data → canvas CSS pixels), `toData(event)` → [x, y],
 * `domain()` → { x: [lo, hi], y: [lo, hi] }, `setDomain(x, y)`, `reset()`, `redraw()`,
 * `axes({ xLabel, yLabel, ticks, format })` (call it from `draw`), `unitsPerPixel()`,
 * `dragging` (the target being dragged, or null), and `ctx`, `box`, `width`, `height`, `canvas`.
 */
export function sceneView(canvas, { width, height, box, x, y, draw, drag = null, pan = false, zoom = false, onView = null }) {
  const ctx = setupCanvas(canvas, width, height);
  const initial = { x: [...x], y: [...y] };
  let sx;
  let sy;
  const view = {
    canvas, ctx, box, width, height, dragging: null,
    px: (v) => sx(v),
    py: (v) => sy(v),
    domain: () => ({ x: [sx.invert(box.left), sx.invert(box.left + box.width)], y: [sy.invert(box.top + box.height), sy.invert(box.top)] }),
    setDomain(xd, yd) {
      sx = scale(xd[0], xd[1], box.left, box.left + box.width);
      sy = scale(yd[0], yd[1], box.top + box.height, box.top);
    },
    reset() {
      view.setDomain(initial.x, initial.y);
      view.redraw();
    },
    unitsPerPixel: () => (sx.invert(box.left + box.width) - sx.invert(box.left)) / box.width,
    redraw() {
      ctx.clearRect(0, 0, width, height);
      draw(ctx, view);
      markFigure();
    },
    axes({ xLabel = '', yLabel = '', ticks = 6, format = (v) => `${+v.toFixed(6)}` } = {}) {
      const { x: xd, y: yd } = view.domain();
      drawAxes(ctx, box, sx, sy, { xTicks: niceTicks(xd[0], xd[1], ticks), yTicks: niceTicks(yd[0], yd[1], ticks), xLabel, yLabel, fmt: format });
    },
    /** The data point under a pointer or mouse event. */
    toData(event) {
      const [cx, cy] = cssPoint(event);
      return [sx.invert(cx), sy.invert(cy)];
    },
  };
  view.setDomain(x, y);

  // The canvas may be drawn smaller than its layout size (max-width: 100%): scale the pointer
  // from the content box (inside the CSS border) to the canvas's CSS pixels.
  function cssPoint(event) {
    const rect = canvas.getBoundingClientRect();
    const [bx, by] = [canvas.clientLeft, canvas.clientTop];
    return [(event.clientX - rect.left - bx) * (width / (rect.width - 2 * bx)), (event.clientY - rect.top - by) * (height / (rect.height - 2 * by))];
  }

  if (drag || pan) canvas.style.touchAction = 'none';
  const active = { id: null, target: null, start: null, last: null, panFrom: null };
  canvas.addEventListener('pointerdown', (event) => {
    if (active.id !== null || event.button > 0) return;
    const point = view.toData(event);
    const target = drag ? drag.hit(point, event) : null;
    if (target === null && !pan) return;
    active.id = event.pointerId;
    active.target = target;
    active.start = point;
    active.last = point;
    active.panFrom = target === null ? { point, domain: view.domain() } : null;
    canvas.setPointerCapture(event.pointerId);
    canvas.classList.add('dragging');
    event.preventDefault();
    if (target !== null) {
      view.dragging = target;
      drag.start?.(target, point);
    }
  });
  canvas.addEventListener('pointermove', (event) => {
    if (event.pointerId !== active.id) {
      if (active.id === null && drag) canvas.classList.toggle('over', drag.hit(view.toData(event), event) !== null);
      return;
    }
    if (active.panFrom) {
      // Shift the rectangle so that the grabbed data point stays under the pointer.
      const { point: p0, domain: d } = active.panFrom;
      view.setDomain(d.x, d.y);
      const [px1, py1] = view.toData(event);
      const dx = p0[0] - px1;
      const dy = p0[1] - py1;
      view.setDomain([d.x[0] + dx, d.x[1] + dx], [d.y[0] + dy, d.y[1] + dy]);
      view.redraw();
      onView?.(view);
      return;
    }
    const point = view.toData(event);
    const delta = [point[0] - active.last[0], point[1] - active.last[1]];
    active.last = point;
    drag.move(active.target, { point, start: active.start, delta });
  });
  const end = (event) => {
    if (event.pointerId !== active.id) return;
    const { target } = active;
    active.id = null;
    active.target = null;
    active.panFrom = null;
    view.dragging = null;
    canvas.classList.remove('dragging');
    if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
    if (target !== null) drag.end?.(target);
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  if (zoom) {
    canvas.addEventListener('wheel', (event) => {
      if (!(event.ctrlKey || event.metaKey)) return; // a plain wheel scrolls the page
      event.preventDefault();
      const [cx, cy] = view.toData(event);
      const k = Math.exp(Math.max(Math.min(event.deltaY, 100), -100) * 0.003);
      const { x: xd, y: yd } = view.domain();
      view.setDomain([cx + (xd[0] - cx) * k, cx + (xd[1] - cx) * k], [cy + (yd[0] - cy) * k, cy + (yd[1] - cy) * k]);
      view.redraw();
      onView?.(view);
    }, { passive: false });
  }
  if (pan || zoom) {
    canvas.addEventListener('dblclick', () => {
      view.reset();
      onView?.(view);
    });
  }
  return view;
}

// ---------------------------------------------------------------- the threshold gauge
// A gauge of a probability against a reporting threshold on [0, 1] (e.g. the existence p of
// a Bernoulli against Γ): the two sides shaded and named, the conventional 0.5 and the
// threshold marked, the value pointed at.

/**
 * Draws on `canvas` (420 × 66 CSS px by default). Options: `value` (its name, default 'p'),
 * `below`, `above` (what each side of the threshold means), `colours` { threshold,
 * conventional }, `conventional` (default 0.5; null for none). `update({ value, threshold })`
 * redraws; a threshold outside [0, 1] is drawn at the end it passed and labelled so.
 */
export function thresholdGauge(canvas, { value: name = 'p', below = 'below', above = 'above', colours = {}, conventional = 0.5, width = 420, height = 66 } = {}) {
  const ctx = setupCanvas(canvas, width, height);
  const b = { left: 12, top: 24, width: width - 24, height: 14 };
  const x = scale(0, 1, b.left, b.left + b.width);
  const { threshold: tColour = '#0072b2', conventional: cColour = '#d55e00' } = colours;
  const tick = (p, colour, lineWidth, dash) => {
    ctx.strokeStyle = colour;
    ctx.lineWidth = lineWidth;
    ctx.setLineDash(dash);
    ctx.beginPath();
    ctx.moveTo(x(p), b.top - 4);
    ctx.lineTo(x(p), b.top + b.height + 4);
    ctx.stroke();
    ctx.setLineDash([]);
  };
  return {
    update({ value, threshold }) {
      ctx.clearRect(0, 0, width, height);
      const g = Math.min(Math.max(threshold, 0), 1);
      ctx.fillStyle = '#fbd5c0';
      ctx.fillRect(b.left, b.top, x(g) - b.left, b.height);
      ctx.fillStyle = '#bbf7d0';
      ctx.fillRect(x(g), b.top, b.left + b.width - x(g), b.height);
      ctx.strokeStyle = '#9aa5b1';
      ctx.lineWidth = 1;
      ctx.strokeRect(b.left, b.top, b.width, b.height);
      ctx.font = '11px system-ui, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'center';
      const mid = b.top + b.height / 2;
      if (x(g) - b.left > ctx.measureText(below).width + 12) haloText(ctx, below, (b.left + x(g)) / 2, mid, '#8a3800');
      if (b.left + b.width - x(g) > ctx.measureText(above).width + 12) haloText(ctx, above, (x(g) + b.left + b.width) / 2, mid, '#065f46');
      ctx.textBaseline = 'top';
      if (conventional !== null) {
        tick(conventional, cColour, 1, [3, 2]);
        ctx.fillStyle = cColour;
        ctx.fillText(String(conventional), x(conventional), b.top + b.height + 5);
      }
      tick(g, tColour, 2, []);
      const gx = Math.min(Math.max(x(g), b.left + 34), b.left + b.width - 34);
      ctx.fillStyle = tColour;
      const label = threshold > 1 ? 'Γ > 1' : threshold < 0 ? 'Γ < 0' : `Γ = ${+threshold.toFixed(3)}`;
      if (conventional === null || Math.abs(gx - x(conventional)) > 44) ctx.fillText(label, gx, b.top + b.height + 5);
      ctx.fillStyle = '#52606d';
      ctx.textAlign = 'left';
      ctx.fillText('0', b.left, b.top + b.height + 5);
      ctx.textAlign = 'right';
      ctx.fillText('1', b.left + b.width, b.top + b.height + 5);
      const p = x(value);
      ctx.fillStyle = '#1f2933';
      ctx.beginPath();
      ctx.moveTo(p, b.top - 1);
      ctx.lineTo(p - 6, b.top - 11);
      ctx.lineTo(p + 6, b.top - 11);
      ctx.fill();
      ctx.textBaseline = 'bottom';
      ctx.textAlign = value > 0.85 ? 'right' : value < 0.15 ? 'left' : 'center';
      ctx.fillText(`${name} = ${+value.toFixed(3)}`, p + (value > 0.85 ? -8 : value < 0.15 ? 8 : 0), b.top - 12);
    },
  };
}
