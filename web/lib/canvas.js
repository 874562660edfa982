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
