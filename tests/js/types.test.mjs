// The npm package's TypeScript declarations type-check a program that uses the contract
// (tests/js/types/usage.ts), under `strict`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

const tsc = (config) => {
  try {
    execFileSync(process.execPath, [path.join(here, 'node_modules/typescript/bin/tsc'), '-p', path.join(here, config)], { encoding: 'utf8' });
  } catch (e) {
    assert.fail(`tsc -p ${config} failed:\n${e.stdout}${e.stderr}`);
  }
};

test('TypeScript declarations', () => tsc('types/tsconfig.json'));

// Issue 26, point 3: a strict consumer with `lib: ["ES2022"]` only (no DOM, no Node types) and no
// `skipLibCheck` type-checks against the package's declarations.
test('TypeScript declarations under strict, lib ES2022, no skipLibCheck', () => tsc('types/tsconfig.es2022.json'));

// Issue 26, point 3: each part's declarations hold only its own names. Every type a part's
// `.d.ts` declares is reached from its functions and classes (or is another name for such a
// type, `export type ActionOut = Action;`), so autocomplete on `fisst/<part>` lists no type of
// another part (scripts/pkg-guards.mjs leaves the others out).
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

test('each part declares only the names its exports reach', () => {
  const ts = createRequire(import.meta.url)('typescript');
  const pkg = path.join(here, 'node_modules/fisst');
  const parts = JSON.parse(readFileSync(path.join(pkg, 'package.json'), 'utf8'))
    .files.filter((f) => f.endsWith('.node.js')).map((f) => f.slice(0, -'.node.js'.length));
  assert.ok(parts.length >= 6, `parts: ${parts}`);
  for (const part of parts) {
    const file = path.join(pkg, `${part}.d.ts`);
    const sf = ts.createSourceFile(file, readFileSync(file, 'utf8'), ts.ScriptTarget.ES2022, true);
    const decls = new Map(); // name -> { kinds, refs, alias }
    for (const st of sf.statements) {
      const name = st.name?.text;
      if (!name) continue;
      const d = decls.get(name) ?? { kinds: new Set(), refs: new Set(), alias: undefined };
      d.kinds.add(ts.SyntaxKind[st.kind]);
      const visit = (n) => {
        if (ts.isTypeReferenceNode(n)) d.refs.add(n.typeName.getText().split('.')[0]);
        if (ts.isExpressionWithTypeArguments(n)) d.refs.add(n.expression.getText().split('.')[0]);
        ts.forEachChild(n, visit);
      };
      ts.forEachChild(st, visit);
      if (ts.isTypeAliasDeclaration(st) && ts.isTypeReferenceNode(st.type) && !st.type.typeArguments) {
        d.alias = st.type.typeName.getText();
      }
      decls.set(name, d);
    }
    const values = ['FunctionDeclaration', 'ClassDeclaration'];
    const roots = [...decls].filter(([n, d]) => values.some((k) => d.kinds.has(k)) || ['InitInput', 'InitOutput', 'SyncInitInput'].includes(n)).map(([n]) => n);
    const reached = new Set(roots);
    const queue = [...roots];
    while (queue.length) {
      for (const r of decls.get(queue.pop()).refs) {
        if (decls.has(r) && !reached.has(r)) {
          reached.add(r);
          queue.push(r);
        }
      }
    }
    const foreign = [...decls].filter(([n, d]) => !reached.has(n) && !(d.alias && reached.has(d.alias))).map(([n]) => n);
    assert.deepEqual(foreign, [], `${part}.d.ts declares names its exports do not reach`);
  }
});

// scripts/pkg-guards.mjs's `ownNames` on a small declaration file: the unreached types go, an
// alias of a reached type stays, and an interface merged into a class (overloads) moves after it.
test('ownNames keeps what the exports reach and places class overloads after the class', async () => {
  const { ownNames } = await import('../../scripts/pkg-guards.mjs');
  const source = `/* tslint:disable */
/** Shown. */
export type Used = { a: Inner };
export interface Inner { b: string }
/** Not used by any export. */
export interface Foreign { c: 'x;y' | "}" }
export type Alias = Used;
export type Alias2 = Foreign;
export interface K {
    /** Overload. */
    m(x: Used): 1;
}
export function f(u: Used): void;
export class K {
    m(x?: Used): number;
}
`;
  const out = ownNames(source);
  for (const kept of ['/* tslint:disable */', '/** Shown. */\nexport type Used', 'export interface Inner', 'export type Alias = Used;', 'export function f']) {
    assert.ok(out.includes(kept), `missing ${kept} in\n${out}`);
  }
  for (const gone of ['Foreign', 'Not used', 'Alias2']) assert.ok(!out.includes(gone), `kept ${gone} in\n${out}`);
  assert.ok(out.indexOf('export interface K') > out.indexOf('export class K'), out);
});
