//! The caps the docs state as numbers agree with their constants.
//!
//! A doc that gives a cap for every reader writes its number with the constant beside it, "an
//! integer in [1, 4096] ([`MAX_GRID_AXIS`])": the TypeScript generator of the JavaScript
//! binding leaves the constant's aside out, so the number is all a JavaScript reader sees.
//! This test reads every doc comment of the crate and checks each number before such an aside
//! against the constant's value, so that a changed constant cannot leave its docs behind.

extern crate std;

use std::path::Path;
use std::string::{String, ToString};
use std::vec::Vec;
use std::{format, fs};

/// The value of each constant a doc names in a cap's aside.
fn value(name: &str) -> Option<f64> {
    use crate::{bernoulli, estimators, fov, gaussian, regions, splitting};
    Some(match name {
        "MAX_REDUCE_INPUT" => splitting::MAX_REDUCE_INPUT as f64,
        "MAX_RUNNALLS_INPUT" => splitting::MAX_RUNNALLS_INPUT as f64,
        "MAX_SCENE_COUNT" => fov::MAX_SCENE_COUNT as f64,
        "MAX_GAUSSIANS" => gaussian::MAX_GAUSSIANS as f64,
        "MAX_CARDINALITY_LEN" => fov::MAX_CARDINALITY_LEN as f64,
        "MAX_VERTICES" => regions::MAX_VERTICES as f64,
        "MAX_GRID_AXIS" => fov::MAX_GRID_AXIS as f64,
        "MAX_VARIANCE_MAP_WORK" => fov::MAX_VARIANCE_MAP_WORK,
        "MAX_DENSITY_GRID_WORK" => fov::MAX_DENSITY_GRID_WORK,
        "MAX_DECISION_MAP_RESOLUTION" => estimators::figures::MAX_DECISION_MAP_RESOLUTION as f64,
        "MAX_IDENTICAL_COMPONENTS" => estimators::figures::MAX_IDENTICAL_COMPONENTS as f64,
        "MAX_ISOTROPIC_DIM" => bernoulli::MAX_ISOTROPIC_DIM as f64,
        "MAX_MMUC_COMPONENTS" => bernoulli::MAX_MMUC_COMPONENTS as f64,
        "MAX_MMUC_PARTICLES" => bernoulli::MAX_MMUC_PARTICLES as f64,
        "MAX_MULTI_BERNOULLI_COMPONENTS" => bernoulli::MAX_MULTI_BERNOULLI_COMPONENTS as f64,
        _ => return None,
    })
}

/// A number as the docs write it: `4096`, `10,000`, `2e8`, `2.5e7`.
fn number(token: &str) -> Option<f64> {
    let t = token.trim_matches(|c: char| matches!(c, '[' | ']' | ',' | ';' | '(' | ')'));
    if !t.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    t.replace(',', "").parse().ok()
}

/// Every doc comment of `dir`'s files (recursively), each file's doc lines joined by spaces.
fn docs(dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            docs(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs")
            && !path.ends_with("doc_caps_tests.rs")
        {
            let text = fs::read_to_string(&path).unwrap();
            let joined: Vec<&str> = text
                .lines()
                .filter_map(|l| {
                    let l = l.trim_start();
                    l.strip_prefix("///").or_else(|| l.strip_prefix("//!"))
                })
                .map(str::trim)
                .collect();
            out.push((path.display().to_string(), joined.join(" ")));
        }
    }
}

/// The asides `([`MAX_…`])` (or `([`MAX_…`](path))`) closing right after the constant, each
/// with the text before it.
fn asides(doc: &str) -> Vec<(&str, &str)> {
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(at) = doc[from..].find("([`MAX_").map(|i| i + from) {
        let name_start = at + 3;
        let Some(name_len) = doc[name_start..].find('`') else {
            break;
        };
        let name = &doc[name_start..name_start + name_len];
        let mut rest = &doc[name_start + name_len + 2..];
        if rest.starts_with('(') {
            rest = rest.find(')').map_or("", |i| &rest[i + 1..]);
        }
        if rest.starts_with(')') {
            found.push((&doc[..at], name));
        }
        from = name_start;
    }
    found
}

#[test]
fn every_cap_a_doc_states_is_its_constant() {
    let mut files = Vec::new();
    docs(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut files,
    );
    let mut checked = 0;
    let mut wrong = Vec::new();
    for (file, doc) in &files {
        for (before, name) in asides(doc) {
            let Some(expected) = value(name) else {
                wrong.push(format!("{file}: `{name}` is not in this test's table"));
                continue;
            };
            // The number is among the last four words before the aside ("at most 10,000
            // Gaussians in all ([`…`])", "[1, 4096] ([`…`])").
            let stated = before.split_whitespace().rev().take(4).find_map(number);
            match stated {
                Some(v) if v == expected => checked += 1,
                other => wrong.push(format!(
                    "{file}: the doc states {other:?} beside `{name}` = {expected}"
                )),
            }
        }
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
    // The 15 asides of the crate when this test was written: it reads them all.
    assert!(checked >= 15, "only {checked} caps checked");
}

#[test]
fn a_wrong_number_is_found() {
    let doc = "an integer in [1, 4095] ([`MAX_GRID_AXIS`]); at most 10,000 ([`MAX_GAUSSIANS`]).";
    let found = asides(doc);
    assert_eq!(found.len(), 2);
    let stated: Vec<Option<f64>> = found
        .iter()
        .map(|(before, _)| before.split_whitespace().rev().take(4).find_map(number))
        .collect();
    assert_eq!(stated, [Some(4095.0), Some(10_000.0)]);
    assert_ne!(stated[0], value("MAX_GRID_AXIS"));
    assert_eq!(stated[1], value("MAX_GAUSSIANS"));
}
