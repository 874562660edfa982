// The boundary fuzzer: drives every exported function of the npm package with valid inputs at
// the edges (specs.mjs) and with malformed ones made from them here (a value replaced by NaN,
// ±Infinity, null, undefined, a string, a ragged or deeply nested array, a negative or
// fractional count, a size past a cap, a cyclic object; an unknown key added; a key removed),
// and checks every call:
//   - no wasm trap (`RuntimeError: unreachable`, out-of-bounds) and no other kind of throw than
//     TypeError / RangeError,
//   - every message starts with the path of a field (an argument name: `options…`, `truth[…]`),
//   - no NaN anywhere in a returned value,
//   - no call longer than its bound,
//   - the module still works afterwards (a canary call returns the right number).
// fast-check shrinks a failing input to a small one; `run.mjs` (make fuzz) and
// `fuzz.test.mjs` (make test) print the failures with the shrunk input.
//
// Besides these, the `extreme` cases replace one number, one array of numbers or every number
// of a valid input by a value from EXTREMES (±1e308, ±Number.MAX_VALUE, 2^53, 2^53 + 2,
// subnormals, the smallest normal, −0): the result must be a RangeError naming the field, or
// a value without NaN. And `runLarge` runs the fixed inputs at each export's size cap
// (specs.mjs, `largeCases`) each in a child process under a watchdog (see there).
//
// Time: every call (each method of a class on its own) is held to its spec's bound, 2 s
// unless the spec says otherwise, on the smaller of its wall-clock and its CPU time (so that
// a machine busy with other work does not fail the run; a call that computes too long fails).
import fc from 'fast-check';
import { fork } from 'node:child_process';
import { readFileSync } from 'node:fs';
import * as fisst from 'fisst';
import { EXTREMES, largeCases, pastCaps, specs } from './specs.mjs';

/** A JSON-ish rendering that survives cycles, NaN, typed arrays, undefined and BigInt. */
export function show(v, depth = 0, seen = new Set()) {
  if (depth > 6) return '…';
  if (typeof v === 'number') return Object.is(v, -0) ? '-0' : String(v);
  if (typeof v === 'bigint') return `${v}n`;
  if (typeof v === 'string') return JSON.stringify(v.length > 60 ? `${v.slice(0, 60)}…` : v);
  if (v === undefined) return 'undefined';
  if (v === null || typeof v !== 'object') return String(v);
  if (seen.has(v)) return '[cyclic]';
  seen.add(v);
  let out;
  if (ArrayBuffer.isView(v)) out = `${v.constructor.name}[${Array.from(v.slice(0, 8)).join(', ')}${v.length > 8 ? ', …' : ''}]`;
  else if (Array.isArray(v)) out = `[${v.slice(0, 12).map((x) => show(x, depth + 1, seen)).join(', ')}${v.length > 12 ? `, … (${v.length})` : ''}]`;
  else out = `{ ${Object.keys(v).slice(0, 16).map((k) => `${k}: ${show(v[k], depth + 1, seen)}`).join(', ')} }`;
  seen.delete(v);
  return out;
}

// ------------------------------------------------------------------ malformed values
function deepArray(n) {
  let a = [1];
  for (let i = 0; i < n; i++) a = [a];
  return a;
}
function deepObject(n) {
  let o = { x: 1 };
  for (let i = 0; i < n; i++) o = { x: o };
  return o;
}
function cyclicObject() {
  const o = { mean: [0, 0] };
  o.cov = o;
  o.self = o;
  return o;
}
function cyclicArray() {
  const a = [1, 2];
  a.push(a);
  return a;
}

/** The malformed values a field can be replaced by. Fresh each time (cycles, arrays). */
const BAD = [
  () => NaN,
  () => Infinity,
  () => -Infinity,
  () => null,
  () => undefined,
  () => '',
  () => 'x',
  () => '1',
  () => true,
  () => ({}),
  () => [],
  () => [[]],
  () => -1,
  () => 1.5,
  () => -0.5,
  () => 2 ** 53,
  () => 1e308,
  () => -1e308,
  () => 5e-324,
  () => [1, [2, 3]],
  () => [[1, 2], [3]],
  () => deepArray(200),
  () => deepObject(200),
  () => cyclicObject(),
  () => cyclicArray(),
  () => new Float64Array([1, NaN]),
  () => 10n,
  () => Symbol('s'),
  () => () => 1,
  () => new Map([['c', 1]]),
];

/** Every path (array of keys) to a node of `v`, the root included. */
function paths(v, prefix = [], out = [], depth = 0) {
  out.push(prefix);
  if (depth > 8 || v === null || typeof v !== 'object') return out;
  // Typed arrays are leaves (replaced whole: a Symbol cannot be stored in one).
  if (ArrayBuffer.isView(v)) return out;
  const keys = Array.isArray(v) ? v.map((_, i) => i) : Object.keys(v);
  for (const k of keys.slice(0, 24)) paths(v[k], [...prefix, k], out, depth + 1);
  return out;
}

/** A deep copy (plain objects, arrays, typed arrays; other values as they are). */
function clone(v) {
  if (ArrayBuffer.isView(v)) return v.slice();
  if (Array.isArray(v)) return v.map(clone);
  const proto = v && typeof v === 'object' ? Object.getPrototypeOf(v) : undefined;
  if (proto === Object.prototype || proto === null) {
    const o = {};
    for (const k of Object.keys(v)) o[k] = clone(v[k]);
    return o;
  }
  return v;
}

function getAt(root, path) {
  let v = root;
  for (const k of path) v = v?.[k];
  return v;
}

/** Sets `root[path] = value` (creating objects on the way), returning the new root. */
function setAt(root, path, value) {
  if (path.length === 0) return value;
  let v = root;
  for (const k of path.slice(0, -1)) {
    if (v[k] === null || typeof v[k] !== 'object') v[k] = {};
    v = v[k];
  }
  v[path[path.length - 1]] = value;
  return root;
}

const UNKNOWN_KEYS = ['aplha', 'extra', 'Mean', 'covariance', '__proto__x', 'c ', ''];

/**
 * Applies mutation `op` (chosen by the integers `a`, `b`, `c`) to a copy of the argument list.
 * Returns `[args, description]`.
 */
export function mutate(name, args, a, b, c) {
  const copy = clone(args);
  const all = paths(copy).filter((p) => p.length > 0);
  const caps = pastCaps[name] ?? [];
  const ops = ['replace', 'replace', 'replace', 'unknownKey', 'deleteKey', 'ragged', 'pastCap'];
  const op = ops[a % ops.length];
  if (op === 'pastCap' && caps.length > 0) {
    const [where, value] = caps[b % caps.length];
    const path = where.split('.').map((k) => (/^\d+$/.test(k) ? Number(k) : k));
    if (copy.length === 0) copy.push({});
    return [setAt(copy, path, value), `${where} = ${show(value)} (past its cap)`];
  }
  if (all.length === 0) {
    // No argument to mutate: pass a bad value as the first argument.
    const bad = BAD[c % BAD.length]();
    return [[bad], `args = [${show(bad)}]`];
  }
  const path = all[b % all.length];
  const target = getAt(copy, path);
  if (op === 'unknownKey') {
    const objects = all.filter((p) => {
      const v = getAt(copy, p);
      return v && typeof v === 'object' && !Array.isArray(v) && !ArrayBuffer.isView(v);
    });
    if (objects.length > 0) {
      const at = objects[b % objects.length];
      const key = UNKNOWN_KEYS[c % UNKNOWN_KEYS.length];
      getAt(copy, at)[key] = 1;
      return [copy, `${at.join('.')}.${JSON.stringify(key)} added`];
    }
  }
  if (op === 'deleteKey') {
    const parent = getAt(copy, path.slice(0, -1));
    if (parent && typeof parent === 'object' && !Array.isArray(parent) && !ArrayBuffer.isView(parent)) {
      delete parent[path[path.length - 1]];
      return [copy, `${path.join('.')} deleted`];
    }
  }
  if (op === 'ragged' && Array.isArray(target) && target.length > 0) {
    const k = c % target.length;
    if (Array.isArray(target[k]) && target[k].length > 0) target[k] = target[k].slice(1);
    else target.push(c % 2 ? 'y' : [1, 2, 3, 4, 5]);
    return [copy, `${path.join('.')} made ragged`];
  }
  const bad = BAD[c % BAD.length]();
  return [setAt(copy, path, bad), `${path.join('.')} = ${show(bad)}`];
}

/** Paths to every number of `v` (array elements and object fields, typed array elements too). */
function numberPaths(v, prefix = [], out = [], depth = 0) {
  if (typeof v === 'number') out.push(prefix);
  if (depth > 8 || v === null || typeof v !== 'object') return out;
  if (v instanceof Float64Array || v instanceof Float32Array) {
    for (let i = 0; i < Math.min(v.length, 64); i++) out.push([...prefix, i]);
    return out;
  }
  if (ArrayBuffer.isView(v)) return out;
  const keys = Array.isArray(v) ? v.map((_, i) => i) : Object.keys(v);
  for (const k of keys.slice(0, 64)) numberPaths(v[k], [...prefix, k], out, depth + 1);
  return out;
}

/**
 * Replaces numbers of a copy of `args` by extreme magnitudes: one number (most often), every
 * number of one array (a whole point, a box corner, a row), or every number of the input.
 * Returns `[args, description]`.
 */
export function extremize(args, a, b, c) {
  const copy = clone(args);
  const all = numberPaths(copy);
  if (all.length === 0) return [copy, 'no number to replace'];
  const value = (k) => EXTREMES[(c + k) % EXTREMES.length];
  const mode = a % 6;
  if (mode <= 3) {
    const path = all[b % all.length];
    setAt(copy, path, value(0));
    return [copy, `extreme: ${path.join('.')} = ${show(value(0))}`];
  }
  if (mode === 4) {
    const parentKey = all[b % all.length].slice(0, -1).join('.');
    const group = all.filter((p) => p.slice(0, -1).join('.') === parentKey);
    group.forEach((p, k) => setAt(copy, p, (a >> 3) % 2 ? value(0) : value(k)));
    return [copy, `extreme: every number of ${parentKey || 'args'} from ${show(value(0))}`];
  }
  all.forEach((p) => setAt(copy, p, value(0)));
  return [copy, `extreme: every number = ${show(value(0))}`];
}

// ------------------------------------------------------------------ checks
/** The path of the first NaN in `v`, or null. */
export function findNaN(v, path = 'result', depth = 0, seen = new Set()) {
  if (typeof v === 'number') return Number.isNaN(v) ? path : null;
  if (v === null || typeof v !== 'object' || depth > 12 || seen.has(v)) return null;
  seen.add(v);
  if (ArrayBuffer.isView(v)) {
    if (v instanceof Float64Array || v instanceof Float32Array) {
      const i = v.findIndex((x) => Number.isNaN(x));
      return i >= 0 ? `${path}[${i}]` : null;
    }
    return null;
  }
  for (const k of Object.keys(v)) {
    const hit = findNaN(v[k], Array.isArray(v) ? `${path}[${k}]` : `${path}.${k}`, depth + 1, seen);
    if (hit) return hit;
  }
  return null;
}

/** Whether the module still computes: OSPA of {0} and {3} with c = 2, p = 1 is 2. */
export function alive() {
  try {
    return fisst.ospa([[0]], [[3]], { c: 2, p: 1 }).distance === 2 && fisst.multiBernoulliCardinality([0.5])[1] === 0.5;
  } catch {
    return false;
  }
}

/** The bound on one call, in ms (issue 26: every call under 2 s in Node at its cap). */
export const DEFAULT_MAX_MS = 2000;

// In a child process of `runLarge`: tells the parent which call is running (for the watchdog's report).
let onCall = null;

/** CPU time of this process so far, in ms (user + system). */
const cpuMs = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};

/**
 * Calls `spec` with `args` and returns null when every check passes, or a description of the
 * failure. `stats` (optional) collects counts; `stats.slowest` is the slowest call seen,
 * `{ ms, wallMs, cpuMs, call }`.
 */
export function check(spec, args, stats) {
  const calls = [];
  // `timed(label, f)`: one call, timed on its own (the class drivers time each method).
  const timed = (label, f) => {
    onCall?.(label);
    const wall0 = performance.now();
    const cpu0 = cpuMs();
    try {
      return f();
    } finally {
      const wallMs = performance.now() - wall0;
      const cpu = cpuMs() - cpu0;
      calls.push({ call: label, wallMs, cpuMs: cpu, ms: Math.min(wallMs, cpu) });
    }
  };
  let result;
  let error;
  try {
    // A spec may drive a class: `call(fisst, args, timed)` constructs, calls its methods, frees.
    result = spec.call ? spec.call(fisst, args, timed) : timed(`${spec.name}()`, () => fisst[spec.name](...args));
  } catch (e) {
    error = e;
  }
  const slowest = calls.reduce((m, x) => (x.ms > m.ms ? x : m), { ms: 0, wallMs: 0, cpuMs: 0, call: '' });
  const ms = slowest.ms;
  if (stats) {
    stats.calls++;
    stats.lastOutcome = error === undefined ? 'returned' : `${error?.name}: ${String(error?.message).slice(0, 200)}`;
    if (ms >= stats.slowestMs) stats.slowest = slowest;
    stats.slowestMs = Math.max(stats.slowestMs, ms);
  }
  if (error !== undefined) {
    if (stats) stats[error?.name === 'TypeError' ? 'typeErrors' : error?.name === 'RangeError' ? 'rangeErrors' : 'otherErrors']++;
    if (error instanceof WebAssembly.RuntimeError) return `wasm trap: ${error.message}`;
    if (!(error instanceof TypeError || error instanceof RangeError)) return `threw ${error?.name ?? typeof error}: ${error?.message ?? String(error)}`;
    const message = error.message;
    const named = spec.roots.some((r) => message.startsWith(r) && /^[.[ :]|^$/.test(message.slice(r.length, r.length + 1)));
    if (!named) return `${error.name} does not start with a field path (${spec.roots.join(', ')}): ${JSON.stringify(message)}`;
  } else {
    if (stats) stats.returned++;
    const nan = findNaN(result);
    if (nan) return `NaN at ${nan}`;
  }
  const bound = spec.maxMs ?? DEFAULT_MAX_MS;
  if (ms > bound) return `${slowest.call} took ${slowest.wallMs.toFixed(0)} ms (CPU ${slowest.cpuMs.toFixed(0)} ms; bound ${bound} ms)`;
  if (!alive()) return 'the module stopped working after this call';
  return null;
}

/**
 * The arbitrary of one fuzz case of `spec`: valid arguments (3 in 8), a malformed mutation of
 * them (3 in 8), or valid arguments with numbers at the extremes (2 in 8).
 */
export function caseOf(spec) {
  return fc.tuple(spec.args, fc.nat(), fc.nat(), fc.nat(), fc.nat()).map(([args, kind, a, b, c]) => {
    if (kind % 8 < 3) return { args, what: 'valid' };
    if (kind % 8 >= 6) {
      const [ext, what] = extremize(args, a, b, c);
      return { args: ext, what };
    }
    const [bad, what] = mutate(spec.name, args, a, b, c);
    return { args: bad, what };
  });
}

export function newStats() {
  return { calls: 0, returned: 0, typeErrors: 0, rangeErrors: 0, otherErrors: 0, slowestMs: 0, slowest: null, known: {} };
}

/** The id of the first of `known` (known-edges.mjs entries) that `message` on `args` of `name` is. */
export function knownEdge(known, name, args, message) {
  for (const edge of known ?? []) {
    try {
      if ((edge.exports ?? [edge.export]).includes(name) && edge.matches(args, message)) return edge.id;
    } catch {
      // a matcher that does not apply to this input
    }
  }
  return null;
}

/**
 * Runs `total` cases spread over the specs by weight, seeded by `seed`. Returns per-spec
 * `{ stats, failure }` where `failure` is null or `{ message, input, shrinks }`.
 */
export function fuzz({ total, seed, only, progress, shrinkMs = 60_000, known = [] }) {
  const chosen = specs.filter((s) => !only || only.includes(s.name));
  const weights = chosen.map((s) => s.weight ?? 1);
  const sum = weights.reduce((a, b) => a + b, 0);
  const report = [];
  for (const [i, spec] of chosen.entries()) {
    const numRuns = Math.max(1, Math.round((total * weights[i]) / sum));
    const stats = newStats();
    let lastMessage = null;
    const prop = fc.property(caseOf(spec), ({ args, what }) => {
      lastMessage = check(spec, args, stats);
      // A failure that is a known edge (known-edges.mjs, the `known` passed in) is counted,
      // with its first input, and not failed.
      const edge = lastMessage && knownEdge(known, spec.name, args, lastMessage);
      if (edge) {
        stats.known[edge] ??= { count: 0, message: lastMessage, input: `${what}: ${spec.name}(${args.map((x) => show(x)).join(', ')})` };
        stats.known[edge].count++;
        return;
      }
      if (lastMessage) throw new Error(lastMessage);
    });
    // Shrinking re-runs the function many times: bound it so one slow failure cannot stall the
    // run (the counterexample is then the smallest found so far).
    const out = fc.check(prop, { numRuns, seed: seed + i, interruptAfterTimeLimit: shrinkMs });
    let failure = null;
    if (out.failed) {
      const cx = out.counterexample?.[0];
      failure = { message: out.errorInstance?.message ?? String(out.error ?? lastMessage), input: cx ? `${cx.what}: ${spec.name}(${cx.args.map((a) => show(a)).join(', ')})` : '?', shrinks: out.numShrinks };
    }
    report.push({ name: spec.name, numRuns, stats, failure });
    progress?.(report[report.length - 1]);
  }
  return report;
}

// ------------------------------------------------------------------ sizes at the caps, under a watchdog
/**
 * Runs the fixed large inputs (specs.mjs, `largeCases`; all of them, or those whose label is in
 * `labels`), one at a time, each in a fresh child process (this file, forked with
 * FISST_FUZZ_CHILD=1) so that a runaway call cannot hang the run or exhaust this process's
 * memory: the child builds the input, runs `check` on it (the call held to its spec's bound, 2
 * s, on min(wall, CPU)) and sends back the outcome; the parent kills it (SIGKILL) when, after
 * the input was built, the child has used `cpuLimitMs` of CPU time (default: the bound + 0.5
 * s, read from /proc/<pid>/stat every 100 ms) or `watchdogMs` of wall time without answering,
 * and reports the case as still running then. Resolves to `[{ label, name, failure, ms, wallMs, cpuMs, known }]`
 * (`failure` null when it passed; a failure that is one of the `known` edges is reported with
 * `known` set to its id instead).
 */
export async function runLarge({ labels, known = [], watchdogMs = 20_000, cpuLimitMs, progress } = {}) {
  const chosen = largeCases.filter((c) => !labels || labels.includes(c.label));
  const out = [];
  for (const c of chosen) {
    const bound = specs.find((s) => s.name === c.name)?.maxMs ?? DEFAULT_MAX_MS;
    const r = await runChild(c, watchdogMs, cpuLimitMs ?? bound + 500);
    const edge = r.failure ? known.find((e) => e.export === c.name && e.largeLabel === c.label)?.id ?? null : null;
    const row = { label: c.label, name: c.name, ...r, known: edge, failure: edge ? null : r.failure, knownFailure: edge ? r.failure : null };
    out.push(row);
    progress?.(row);
  }
  return out;
}

/** The CPU time (user + system) of process `pid` in ms, from /proc; null where there is none. */
function childCpuMs(pid) {
  try {
    const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return ((Number(fields[11]) + Number(fields[12])) * 1000) / CLOCK_TICKS;
  } catch {
    return null;
  }
}
const CLOCK_TICKS = 100; // USER_HZ on Linux

function runChild(c, watchdogMs, cpuLimitMs) {
  return new Promise((resolve) => {
    const child = fork(new URL(import.meta.url), [], { env: { ...process.env, FISST_FUZZ_CHILD: '1' }, execArgv: ['--max-old-space-size=4096'], serialization: 'advanced', stdio: ['ignore', 'ignore', 'pipe', 'ipc'] });
    let stderr = '';
    child.stderr.on('data', (d) => {
      stderr = (stderr + d).slice(-2000);
    });
    let timer = null;
    let done = false;
    const finish = (r) => {
      if (done) return;
      done = true;
      clearTimeout(timer);
      if (child.exitCode === null && child.signalCode === null) child.kill('SIGKILL');
      resolve(r);
    };
    let running = '';
    child.on('message', (m) => {
      if (m.calling) {
        running = ` in ${m.calling}`;
        return;
      }
      if (!m.built) return finish(m);
      // The input is built: the call starts now, and the watchdog with it. It polls the child's
      // CPU time (Linux: /proc/<pid>/stat) and kills it once that passes `cpuLimitMs` (the
      // call has then failed its bound whatever the load of the machine), or once the wall
      // time passes `watchdogMs` (elsewhere, or when the machine is too busy to tell).
      const wall0 = performance.now();
      const cpu0 = childCpuMs(child.pid);
      const poll = () => {
        const wallMs = performance.now() - wall0;
        const cpu = cpu0 === null ? null : childCpuMs(child.pid) - cpu0;
        if (cpu !== null && cpu > cpuLimitMs) {
          return finish({ failure: `still running${running} after ${cpu.toFixed(0)} ms of CPU time (${wallMs.toFixed(0)} ms wall; killed by the watchdog)`, wallMs, cpuMs: cpu, ms: Math.min(cpu, wallMs), killed: true, call: running.slice(4) });
        }
        if (wallMs > watchdogMs) {
          return finish({ failure: `still running${running} after ${wallMs.toFixed(0)} ms of wall time${cpu === null ? '' : ` (${cpu.toFixed(0)} ms CPU)`} (killed by the watchdog)`, wallMs, cpuMs: cpu, ms: Math.min(cpu ?? wallMs, wallMs), killed: true, call: running.slice(4) });
        }
        timer = setTimeout(poll, 100);
      };
      timer = setTimeout(poll, 100);
    });
    child.on('exit', (code, signal) => finish({ failure: `the child process died (exit ${code}, signal ${signal}): ${stderr.trim().split('\n').slice(-3).join(' | ')}`, wallMs: null, cpuMs: null, ms: null }));
    child.send({ label: c.label });
    // Building a 10^6-element input can take a while: a last-resort bound on the whole child.
    setTimeout(() => finish({ failure: `the child did not finish building its input within 120 s`, ms: null }), 120_000).unref();
  });
}

if (process.env.FISST_FUZZ_CHILD === '1' && process.send) {
  process.once('message', ({ label }) => {
    const c = largeCases.find((x) => x.label === label);
    const spec = specs.find((s) => s.name === c.name);
    const args = c.args();
    onCall = (label) => process.send({ calling: label });
    process.send({ built: true });
    const stats = newStats();
    let failure;
    try {
      failure = check(spec, args, stats);
    } catch (e) {
      failure = `the harness threw ${e?.name}: ${e?.message}`;
    }
    const s = stats.slowest ?? { ms: null, wallMs: null, cpuMs: null, call: '' };
    process.send({ failure, outcome: stats.lastOutcome, ms: s.ms, wallMs: s.wallMs, cpuMs: s.cpuMs, call: s.call }, () => process.exit(0));
  });
}

// ------------------------------------------------------------------ every numeric field at every extreme
/**
 * The systematic sweep (`make fuzz`): for `inputs` valid inputs of each spec (seeded), every
 * number of the input (up to 64) replaced in turn by every value of EXTREMES, each checked.
 * Returns per spec `{ name, calls, failures: [{ message, input }] (the first of each distinct
 * message shape), known: { id: count } }`.
 */
export function sweepExtremes({ seed, inputs = 2, only, known = [], progress }) {
  const out = [];
  for (const [i, spec] of specs.filter((s) => !only || only.includes(s.name)).entries()) {
    const row = { name: spec.name, calls: 0, failures: [], known: {} };
    const seen = new Set();
    for (const args of fc.sample(spec.args, { numRuns: inputs, seed: seed + i })) {
      for (const path of numberPaths(args).slice(0, 64)) {
        for (const value of EXTREMES) {
          const copy = setAt(clone(args), path, value);
          const message = check(spec, copy);
          row.calls++;
          if (!message) continue;
          const edge = knownEdge(known, spec.name, copy, message);
          if (edge) {
            row.known[edge] = (row.known[edge] ?? 0) + 1;
            continue;
          }
          const shape = message.replace(/[-\d.e+]+/g, '#');
          if (seen.has(shape)) continue;
          seen.add(shape);
          row.failures.push({ message, input: `${path.join('.')} = ${show(value)}: ${spec.name}(${copy.map((a) => show(a)).join(', ')})` });
        }
      }
    }
    out.push(row);
    progress?.(row);
  }
  return out;
}
