//! Writes the TypeScript declarations of the core's own types for the part being built.
//!
//! The bindings read and write the core's option and result types (serde, with the core's
//! `serde` feature) under JavaScript names (`src/names_rule.rs`). Their TypeScript is generated
//! here, from the core's source: every type that the part's exported functions name in an
//! `unchecked_param_type` / `unchecked_return_type` and that the core derives serde for (with
//! the types it holds), with its doc comments, fields in JavaScript names, `Option` and
//! defaulted fields optional. Types the binding still declares itself (Tsify) are left out. The
//! result is `$OUT_DIR/core_types.d.ts`, which `src/lib.rs` adds to the module's `.d.ts`; a part
//! gets only its own names, since each part is built alone (`scripts/build-pkg.sh`).
use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

use syn::Item;

#[path = "src/names_rule.rs"]
#[allow(dead_code)]
mod names_rule;
#[path = "ts_aliases.rs"]
mod ts_aliases;
#[path = "tsgen.rs"]
mod tsgen;
use tsgen::{TokStr, cfg_enabled, collect, item_attrs};

/// The identifiers in a TypeScript type text that may name a declared type.
fn type_names(ts: &str) -> impl Iterator<Item = &str> {
    ts.split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
        .filter(|w| w.starts_with(|c: char| c.is_ascii_uppercase()))
}

/// TypeScript text without its comments (`/* … */`, `// …`).
fn without_comments(ts: &str) -> String {
    let mut out = String::new();
    let mut rest = ts;
    while let Some(i) = rest.find('/') {
        out.push_str(&rest[..i]);
        let close = match &rest[i + 1..] {
            r if r.starts_with('*') => "*/",
            r if r.starts_with('/') => "\n",
            _ => {
                out.push('/');
                rest = &rest[i + 1..];
                continue;
            }
        };
        let after = &rest[i + 2..];
        rest = after.find(close).map_or("", |e| &after[e + close.len()..]);
    }
    out + rest
}

/// Whether a Cargo feature of the crate is enabled in this build.
fn feature_on(f: &str) -> bool {
    std::env::var_os(format!(
        "CARGO_FEATURE_{}",
        f.to_uppercase().replace('-', "_")
    ))
    .is_some()
}

fn main() {
    let manifest = std::env::var("CARGO_MANIFEST_DIR").unwrap();
    let wasm_src = Path::new(&manifest).join("src");
    let core_src = Path::new(&manifest).join("../core/src");
    println!("cargo:rerun-if-changed={}", wasm_src.display());
    println!("cargo:rerun-if-changed={}", core_src.display());
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=tsgen.rs");
    println!("cargo:rerun-if-changed=ts_aliases.rs");

    // the part's modules (`#[cfg(feature = "x")] mod y;` in lib.rs, for the enabled features),
    // and in them the items compiled for the part: the names its functions take and return
    // (`unchecked_param_type = "…"`, `#[tsify(type = "…")]`), the names its own TypeScript
    // holds, and those the binding declares
    let lib = syn::parse_file(&fs::read_to_string(wasm_src.join("lib.rs")).unwrap()).unwrap();
    let mut roots = BTreeSet::new();
    let mut mentioned = BTreeSet::new();
    let mut declared: BTreeSet<String> = ts_aliases::ALIASES
        .iter()
        .map(|(name, _, _)| name.to_string())
        .collect();
    for item in &lib.items {
        let Item::Mod(m) = item else { continue };
        if !cfg_enabled(&m.attrs, &feature_on) {
            continue;
        }
        let path = wasm_src.join(format!("{}.rs", m.ident));
        let file = syn::parse_file(&fs::read_to_string(&path).unwrap()).unwrap();
        for item in &file.items {
            if !cfg_enabled(item_attrs(item), &feature_on) {
                continue;
            }
            if let Item::Const(c) = item
                && let syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Str(ts),
                    ..
                }) = &*c.expr
            {
                mentioned.extend(type_names(&without_comments(&ts.value())).map(str::to_string));
            }
            let text = item.to_token_stream_string();
            for piece in text.split("type = \"").skip(1) {
                let ts = piece.split('"').next().unwrap_or("");
                roots.extend(type_names(ts).map(str::to_string));
            }
            // an alias the part declares for a core type (`export type
            // LinearAssignmentResult = Assignment;`) makes that core type a root
            for piece in text.split("export type ").skip(1) {
                let rhs = piece.split(';').next().unwrap_or("");
                if let Some((_, rhs)) = rhs.split_once('=') {
                    roots.extend(type_names(rhs).map(str::to_string));
                }
            }
        }
    }
    for e in fs::read_dir(&wasm_src).unwrap() {
        let path = e.unwrap().path();
        if path.extension().is_some_and(|x| x == "rs") {
            let text = fs::read_to_string(&path).unwrap();
            let file = syn::parse_file(&text).unwrap();
            for item in file.items {
                match item {
                    Item::Struct(s) => {
                        declared.insert(s.ident.to_string());
                    }
                    Item::Enum(e) => {
                        declared.insert(e.ident.to_string());
                    }
                    _ => {}
                }
            }
            for key in ["export type ", "export interface "] {
                for piece in text.split(key).skip(1) {
                    declared.extend(type_names(piece).take(1).map(str::to_string));
                }
            }
        }
    }

    let mut defs = BTreeMap::new();
    collect(&core_src, &mut defs);
    let (out, warnings) =
        tsgen::part_declarations(&defs, &roots, &mentioned, &declared, ts_aliases::ALIASES);
    for w in warnings {
        println!("cargo:warning=TypeScript of the core's types: {w}");
    }
    let out_dir = std::env::var("OUT_DIR").unwrap();
    fs::write(Path::new(&out_dir).join("core_types.d.ts"), out).unwrap();
}
