// A gauge of a probability against a reporting threshold on [0, 1] (e.g. the existence p of
// a Bernoulli against Γ): the two sides shaded and named, the conventional 0.5 and the
// threshold marked, the value pointed at.
import { setupCanvas, scale } from './canvas.js';
import { haloText } from './draw.js';

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
