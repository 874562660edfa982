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
