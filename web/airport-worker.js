// The airport run of web/airport.js in a module Web Worker (paper 001, Section V-C): the
// scenario (airportScenario), then the GM Bernoulli filter and the Bernoulli particle filter
// on the same reports, one message per step, so that the page never waits for the particle
// filter. A worker does not see the page's import map: it imports the package by path.
import init, * as fisst from './pkg/filters.js';

const ready = init();
let current = 0; // the run being computed; a newer request stops the older one

/** The report discs of step k as the filters take them (Region[]). */
const regionsOf = (s, k) => s.reports[k].map((a) => ({ disc: { center: s.anchors[a].position, radius: s.anchors[a].radius } }));

/** The estimate of a filter as posted: existence, MMSE mean and covariance. */
const estimateOf = (f) => {
  const { existence, mean, cov } = f.estimate();
  return { existence, mean, cov };
};

async function run({ id, seed, steps, particles }) {
  await ready;
  const t0 = performance.now();
  const s = fisst.airportScenario({ seed, steps });
  postMessage({ type: 'scenario', id, scenario: s, ms: performance.now() - t0 });
  const gm = new fisst.GmBernoulliFilter(s.config);
  const pf = new fisst.ParticleBernoulliFilter({ ...s.config, particles });
  try {
    for (let k = 0; k < s.reports.length; k++) {
      if (id !== current) return;
      const reports = regionsOf(s, k);
      const a = performance.now();
      gm.predict();
      const info = gm.update(reports);
      const b = performance.now();
      pf.predict();
      pf.update(reports);
      const c = performance.now();
      // Particle positions (x, y) for the cloud, as a transferable Float32Array.
      const cloud = pf.particles;
      const xy = new Float32Array(2 * cloud.length);
      cloud.forEach((p, i) => { xy[2 * i] = p[0]; xy[2 * i + 1] = p[1]; });
      postMessage({
        type: 'step', id, k,
        gm: { ...estimateOf(gm), mixture: gm.mixture, splitComponents: info.splitComponents, delta: info.delta },
        pf: { ...estimateOf(pf), cloud: xy },
        ms: { gm: b - a, pf: c - b },
      }, [xy.buffer]);
      await new Promise((r) => setTimeout(r, 0)); // let a newer request in
    }
    postMessage({ type: 'done', id, ms: performance.now() - t0 });
  } finally {
    gm.free();
    pf.free();
  }
}

onmessage = (e) => {
  current = e.data.id;
  run(e.data).catch((err) => postMessage({ type: 'error', id: e.data.id, message: String(err?.message ?? err) }));
};
