// Small canvas helpers shared by the demo pages (no dependencies).

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

/** A linear map from [d0, d1] to [p0, p1]. */
export function scale(d0, d1, p0, p1) {
  const f = (x) => p0 + ((x - d0) / (d1 - d0)) * (p1 - p0);
  f.invert = (p) => d0 + ((p - p0) / (p1 - p0)) * (d1 - d0);
  return f;
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

/** Evenly spaced ticks from a to b inclusive. */
export function ticks(a, b, n) {
  return Array.from({ length: n + 1 }, (_, i) => a + ((b - a) * i) / n);
}

/** Formats a number compactly for readouts. */
export function fmt(x, digits = 4) {
  if (x === null || x === undefined) return '—';
  if (!Number.isFinite(x)) return String(x);
  if (x !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e5)) return x.toExponential(digits - 1);
  return Number(x.toFixed(digits)).toString();
}

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
