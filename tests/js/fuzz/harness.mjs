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
import fc from 'fast-check';
import * as fisst from 'fisst';
import { pastCaps, specs } from './specs.mjs';

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

const DEFAULT_MAX_MS = 5000;

/**
 * Calls `spec` with `args` and returns null when every check passes, or a description of the
 * failure. `stats` (optional) collects counts.
 */
export function check(spec, args, stats) {
  const start = performance.now();
  let result;
  let error;
  try {
    // A spec may drive a class: `call(fisst, args)` constructs, calls its methods, frees.
    result = spec.call ? spec.call(fisst, args) : fisst[spec.name](...args);
  } catch (e) {
    error = e;
  }
  const ms = performance.now() - start;
  if (stats) {
    stats.calls++;
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
  if (ms > (spec.maxMs ?? DEFAULT_MAX_MS)) return `took ${ms.toFixed(0)} ms (bound ${spec.maxMs ?? DEFAULT_MAX_MS} ms)`;
  if (!alive()) return 'the module stopped working after this call';
  return null;
}

/** The arbitrary of one fuzz case of `spec`: valid arguments, or a mutation of them. */
export function caseOf(spec) {
  return fc.tuple(spec.args, fc.nat(), fc.nat(), fc.nat(), fc.nat()).map(([args, kind, a, b, c]) => {
    if (kind % 2 === 0) return { args, what: 'valid' };
    const [bad, what] = mutate(spec.name, args, a, b, c);
    return { args: bad, what };
  });
}

export function newStats() {
  return { calls: 0, returned: 0, typeErrors: 0, rangeErrors: 0, otherErrors: 0, slowestMs: 0 };
}

/**
 * Runs `total` cases spread over the specs by weight, seeded by `seed`. Returns per-spec
 * `{ stats, failure }` where `failure` is null or `{ message, input, shrinks }`.
 */
export function fuzz({ total, seed, only, progress, shrinkMs = 60_000 }) {
  const chosen = specs.filter((s) => !only || only.includes(s.name));
  const weights = chosen.map((s) => s.weight ?? 1);
  const sum = weights.reduce((a, b) => a + b, 0);
  const report = [];
  for (const [i, spec] of chosen.entries()) {
    const numRuns = Math.max(1, Math.round((total * weights[i]) / sum));
    const stats = newStats();
    let lastMessage = null;
    const prop = fc.property(caseOf(spec), ({ args }) => {
      lastMessage = check(spec, args, stats);
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
