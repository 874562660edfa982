// A scene view: a HiDPI canvas showing a rectangle of data coordinates, with dragging of the
// page's objects, and (opt-in) panning and zooming, all in data coordinates.
import { setupCanvas, scale, drawAxes, niceTicks } from './canvas.js';
import { markFigure } from './timing.js';

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
