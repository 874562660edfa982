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
