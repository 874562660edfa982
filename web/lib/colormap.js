// Perceptually uniform, colour-blind-safe colour maps, density images and their legend.
//
// viridis and cividis: 64 samples of d3-scale-chromatic 3.1.1 (viridis is matplotlib's, by
// van der Walt and Smith, CC0; cividis is Nuñez, Anderton and Renslow 2018, made for colour
// vision deficiency); linear interpolation between samples is within one unit of 8-bit
// colour of the originals. blues and greys: white to one colour, linear in OKLab (equal steps
// of perceived lightness by construction; a single hue reads the same under every colour
// vision deficiency) — light maps for backgrounds under coloured overlays.

const SAMPLES = {
  viridis: '44015446075a470d6047136548186a481d6f482374482878472d7b46327e453781443b844240864045883e49893d4e8a3a538b38588c365c8d34608d32648e31688e2f6c8e2d708e2c738e2a778e297b8e277f8e26828e24868e238a8d218e8d20928c1f968b1f9a8a1f9e891fa18721a58523a98326ad812ab07f2fb47c35b7793bbb7542be714ac16d52c5695ac86465cb5e6ece5877d15381d34d8bd64695d840a0da39aadc32b5de2bc0df25cae11fd5e21adfe318eae51af4e61efde725',
  cividis: '00205100235800265d002961012c65052e6809316a0d346b12376c173a6d1c3d6e223f6e27426e2d456e33486e384b6e3e4e6e43516d48546d4d566d52596e575c6e5b5f6e60626f64656f6868706c6b70706e717371727774737a77737e7a74817d758480768783778b86778e8978928d789590789993789c9678a09a78a49d78a8a077aca476b1a775b5aa73baae71bfb16fc3b56dc8b86bcdbc68d3c065d8c362ddc75fe2cb5ce6cf59ebd255efd652f3da4ff7de4cfae249fce647fdea45',
  blues: 'ffffffeff3f7dfe6f0cfdae8c0cee0b1c2d8a1b6d192aac9849ec17593b96687b1587ca94a70a13b65992d59911d4e89',
  greys: 'fffffff1f2f3e3e5e7d5d8dcc7ccd0babfc5adb3b9a0a7ae939ba3868f9879838d6d7882616d7855626d4957633e4c59',
};

/** Colour-blind-safe categorical colours (Okabe and Ito 2008), for lines and markers. */
export const CATEGORICAL = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9', '#000000', '#f0e442'];

const cache = new Map();

/**
 * The colour map `name` (viridis, cividis, blues, greys) as a 256-entry lookup table:
 * `{ name, lut: Uint8ClampedArray(768), rgb(t) → [r, g, b], css(t) → 'rgb(…)' }` for t in [0, 1]
 * (clamped).
 */
export function colormap(name) {
  if (cache.has(name)) return cache.get(name);
  const hex = SAMPLES[name];
  if (!hex) throw new TypeError(`unknown colour map ${name}: one of ${Object.keys(SAMPLES).join(', ')}`);
  const stops = Array.from({ length: hex.length / 6 }, (_, i) => [0, 2, 4].map((k) => parseInt(hex.slice(6 * i + k, 6 * i + k + 2), 16)));
  const lut = new Uint8ClampedArray(256 * 3);
  for (let n = 0; n < 256; n++) {
    const u = (n / 255) * (stops.length - 1);
    const k = Math.min(Math.floor(u), stops.length - 2);
    const f = u - k;
    for (let c = 0; c < 3; c++) lut[3 * n + c] = Math.round(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]));
  }
  const index = (t) => Math.round(255 * Math.min(Math.max(Number.isFinite(t) ? t : 0, 0), 1));
  const rgb = (t) => {
    const n = 3 * index(t);
    return [lut[n], lut[n + 1], lut[n + 2]];
  };
  const map = { name, lut, rgb, css: (t) => `rgb(${rgb(t).join(',')})` };
  cache.set(name, map);
  return map;
}

/**
 * An `nx` × `ny` image (an offscreen canvas) of row-major `values` (y outer, growing upwards,
 * as `mixtureDensityGrid` returns them) coloured by `map` at t = value / vmax (`scale`
 * 'linear', the default) or t = √(value / vmax) ('sqrt', which brings out low densities; give
 * the colour bar the same scale). `vmax` defaults to the largest value.
 */
export function heatImage(values, nx, ny, { map = 'viridis', vmax = null, scale = 'linear' } = {}) {
  const transform = scale === 'sqrt' ? Math.sqrt : null;
  const { lut } = colormap(map);
  let top = vmax;
  if (top === null) {
    top = 0;
    for (const v of values) if (v > top) top = v;
  }
  const k = top > 0 ? 1 / top : 0;
  const image = document.createElement('canvas');
  image.width = nx;
  image.height = ny;
  const ctx = image.getContext('2d');
  const data = ctx.createImageData(nx, ny);
  const out = data.data;
  for (let j = 0; j < ny; j++) {
    const row = ny - 1 - j; // canvas rows grow downwards
    for (let i = 0; i < nx; i++) {
      let t = values[j * nx + i] * k;
      if (transform) t = transform(t);
      const n = 3 * Math.round(255 * Math.min(Math.max(t || 0, 0), 1));
      const o = 4 * (row * nx + i);
      out[o] = lut[n];
      out[o + 1] = lut[n + 1];
      out[o + 2] = lut[n + 2];
      out[o + 3] = 255;
    }
  }
  ctx.putImageData(data, 0, 0);
  return image;
}

/**
 * A colour-bar legend appended to `container`: a gradient strip of `map` with its label and
 * the values at both ends and in the middle (`scale` as for heatImage). `update({ max, min,
 * label, map, scale })` redraws it; `label` is HTML.
 */
export function colorbar(container, { map = 'viridis', label = '', min = 0, max = 1, scale = 'linear', format = (v) => String(v) } = {}) {
  const el = document.createElement('div');
  el.className = 'colorbar';
  el.innerHTML = '<span class="colorbar-label"></span><span class="colorbar-strip" role="img"></span>'
    + '<span class="colorbar-ticks"><span></span><span></span><span></span></span>';
  container.append(el);
  const state = { map, label, min, max, scale, format };
  const update = (changes = {}) => {
    Object.assign(state, changes);
    const cm = colormap(state.map);
    const stops = Array.from({ length: 11 }, (_, i) => cm.css(i / 10));
    const strip = el.querySelector('.colorbar-strip');
    strip.style.background = `linear-gradient(to right, ${stops.join(', ')})`;
    strip.setAttribute('aria-label', `${state.map} colour scale from ${state.format(state.min)} to ${state.format(state.max)}`);
    el.querySelector('.colorbar-label').innerHTML = state.label;
    // The value at the middle of the strip: t = 0.5 after the transform.
    const inv = state.scale === 'sqrt' ? 0.25 : 0.5;
    const mid = state.min + inv * (state.max - state.min);
    const [a, b, c] = el.querySelectorAll('.colorbar-ticks span');
    a.textContent = state.format(state.min);
    b.textContent = state.format(mid);
    c.textContent = state.format(state.max);
  };
  update();
  return { element: el, update };
}

/**
 * The `grid` option of `mixtureDensityGrid` whose nx × ny cells tile the rectangle x × y
 * (values at the cell centres), so that heatImage's pixels cover it exactly.
 */
export function cellGrid([x0, x1], [y0, y1], nx, ny = nx) {
  const [hx, hy] = [(x1 - x0) / nx, (y1 - y0) / ny];
  return { x: [x0 + hx / 2, x1 - hx / 2, nx], y: [y0 + hy / 2, y1 - hy / 2, ny] };
}

/**
 * Cells [nx, ny] for a density image of the rectangle x × y (square cells) that costs at
 * most `budget` evaluations of `terms` terms each (e.g. mixture components): at most
 * `maxCells` and at least 24 across.
 */
export function cellCounts([x0, x1], [y0, y1], { maxCells = 125, budget = 1e6, terms = 1 } = {}) {
  const aspect = (y1 - y0) / (x1 - x0);
  const nx = Math.max(24, Math.min(maxCells, Math.floor(Math.sqrt(budget / Math.max(terms, 1) / aspect))));
  return [nx, Math.max(1, Math.round(nx * aspect))];
}
