// Regions (fields of view) as the fisst package takes them — { box: { min, max } },
// { polygon: [[x, y], …] }, { disc: { center, radius } } — drawn, hit-tested and edited in a
// scene view (see scene.js).

/** 'box', 'polygon' or 'disc'. */
export const kindOf = (region) => Object.keys(region)[0];

/** The region's outline as a Path2D in the view's canvas pixels. */
export function regionPath(view, region) {
  const { px, py } = view;
  const path = new Path2D();
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    path.rect(px(min[0]), py(max[1]), px(max[0]) - px(min[0]), py(min[1]) - py(max[1]));
  } else if (kind === 'disc') {
    const { center, radius } = region.disc;
    path.arc(px(center[0]), py(center[1]), px(radius) - px(0), 0, 2 * Math.PI);
  } else {
    region.polygon.forEach(([x, y], k) => (k === 0 ? path.moveTo(px(x), py(y)) : path.lineTo(px(x), py(y))));
    path.closePath();
  }
  return path;
}

/** Whether the data point lies inside the region's outline (even-odd rule). */
export function insideRegion(view, region, [x, y]) {
  const dpr = window.devicePixelRatio || 1;
  // isPointInPath takes bitmap pixels; the path is scaled by the context's dpr transform.
  return view.ctx.isPointInPath(regionPath(view, region), view.px(x) * dpr, view.py(y) * dpr, 'evenodd');
}

/** The draggable handles of a region, in data coordinates: box corners, polygon vertices, the disc's rim. */
export function handles(region) {
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    return [[min[0], min[1]], [max[0], min[1]], [max[0], max[1]], [min[0], max[1]]];
  }
  if (kind === 'disc') {
    const { center, radius } = region.disc;
    return [[center[0] + radius, center[1]]];
  }
  return region.polygon.map((p) => [...p]);
}

/** The region moved by [dx, dy]. */
export function translate(region, [dx, dy]) {
  const kind = kindOf(region);
  if (kind === 'box') {
    const { min, max } = region.box;
    return { box: { min: [min[0] + dx, min[1] + dy], max: [max[0] + dx, max[1] + dy] } };
  }
  if (kind === 'disc') {
    const { center, radius } = region.disc;
    return { disc: { center: [center[0] + dx, center[1] + dy], radius } };
  }
  return { polygon: region.polygon.map(([x, y]) => [x + dx, y + dy]) };
}

/** The region with handle `h` moved to the data point [x, y] (sizes stay ≥ `gap`). */
export function reshape(region, h, [x, y], gap = 0.1) {
  const kind = kindOf(region);
  if (kind === 'box') {
    const min = [...region.box.min];
    const max = [...region.box.max];
    if (h === 0 || h === 3) min[0] = Math.min(x, max[0] - gap); else max[0] = Math.max(x, min[0] + gap);
    if (h === 0 || h === 1) min[1] = Math.min(y, max[1] - gap); else max[1] = Math.max(y, min[1] + gap);
    return { box: { min, max } };
  }
  if (kind === 'disc') {
    const { center } = region.disc;
    return { disc: { center, radius: Math.max(Math.hypot(x - center[0], y - center[1]), gap) } };
  }
  const polygon = region.polygon.map((p) => [...p]);
  polygon[h] = [x, y];
  return { polygon };
}

/** A check for URL state: an array of well-formed regions. */
export function validRegions(regions) {
  const num = (v) => typeof v === 'number' && Number.isFinite(v);
  const pt = (p) => Array.isArray(p) && p.length === 2 && p.every(num);
  return Array.isArray(regions) && regions.length > 0 && regions.every((r) => {
    if (!r || typeof r !== 'object' || Object.keys(r).length !== 1) return false;
    if (r.box) return pt(r.box.min) && pt(r.box.max) && r.box.min[0] < r.box.max[0] && r.box.min[1] < r.box.max[1];
    if (r.disc) return pt(r.disc.center) && num(r.disc.radius) && r.disc.radius > 0;
    return Array.isArray(r.polygon) && r.polygon.length >= 3 && r.polygon.every(pt);
  });
}

/** Draws a region's handles (white squares, 8 px) with an outline in `colour`. */
export function drawHandles(ctx, view, region, colour) {
  ctx.fillStyle = '#ffffff';
  ctx.strokeStyle = colour;
  ctx.lineWidth = 1.5;
  for (const [x, y] of handles(region)) {
    ctx.fillRect(view.px(x) - 4, view.py(y) - 4, 8, 8);
    ctx.strokeRect(view.px(x) - 4, view.py(y) - 4, 8, 8);
  }
}

/** Where to write a region's name (data coordinates): its top-left handle, or above a disc's left rim. */
export function labelAnchor(region) {
  if (kindOf(region) === 'disc') {
    const { center, radius } = region.disc;
    return [center[0] - radius * 0.7, center[1] + radius * 0.75];
  }
  return handles(region).reduce(([ax, ay], [x, y]) => (y > ay || (y === ay && x < ax) ? [x, y] : [ax, ay]));
}
