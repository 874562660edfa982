//! Native half of the native ⇄ wasm parity check.
//!
//! `tests/data/parity.json` holds seeded inputs and the outputs the native build computes for
//! them, bit for bit. This test recomputes them natively (so drift is caught here), and
//! `tests/js/contract.test.mjs` recomputes them with the npm package (so any difference between
//! the wasm and native builds is caught there). Regenerate after an intended change with
//! `FISST_BLESS=1 cargo test -p fisst-tests --test parity`.

use fisst::cardinality::multi_bernoulli_cardinality;
use fisst::estimators::multi_bernoulli::{SetMetric, optimal_estimate};
use fisst::metrics::{Gospa, Ospa};
use fisst_tests::{Lcg, data_path};
use serde_json::{Value, json};

fn points(rng: &mut Lcg, n: usize, dim: usize, spread: f64) -> Vec<Vec<f64>> {
    (0..n)
        .map(|_| (0..dim).map(|_| spread * rng.uniform()).collect())
        .collect()
}

fn build() -> Value {
    let mut rng = Lcg::new(2026);
    let mut gospa = vec![];
    let mut ospa = vec![];
    for t in 0..24 {
        let dim = 1 + t % 3;
        let (n, m) = (rng.below(9), rng.below(9));
        let truth = points(&mut rng, n, dim, 10.0);
        let estimate = points(&mut rng, m, dim, 10.0);
        let c = [0.7, 2.0, 5.0][t % 3];
        let p = [1.0, 2.0, 2.5, 3.0][t % 4];
        let alpha = [2.0, 2.0, 1.0, 0.5][(t / 2) % 4];
        let g = Gospa::new(c, p, alpha).unwrap();
        let expected = if alpha == 2.0 {
            let d = g.decompose(&truth, &estimate).unwrap();
            json!({"distance": d.distance, "localisation": d.localisation,
                   "assignment": d.assignment.iter().map(|&(i, j)| [i, j]).collect::<Vec<_>>()})
        } else {
            json!({"distance": g.distance(&truth, &estimate).unwrap()})
        };
        gospa.push(json!({"truth": truth, "estimate": estimate, "c": c, "p": p,
                          "alpha": alpha, "expected": expected}));
        let o = Ospa::new(c, p)
            .unwrap()
            .decompose(&truth, &estimate)
            .unwrap();
        ospa.push(json!({"truth": truth, "estimate": estimate, "c": c, "p": p,
                         "expected": [o.distance, o.localisation, o.cardinality]}));
    }
    let mut cardinality = vec![];
    let mut optimal = vec![];
    for t in 0..8 {
        let n = [3, 10, 40, 200][t % 4];
        let existence: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        let pmf = multi_bernoulli_cardinality(&existence).unwrap();
        cardinality.push(json!({"existence": existence, "expected": pmf}));
        for (name, metric) in [
            ("gospa", SetMetric::GOSPA),
            ("ospa", SetMetric::Ospa),
            ("uospa", SetMetric::Uospa),
        ] {
            let (c, p) = ([1.0, 3.0][t % 2], [2.0, 1.0][t % 2]);
            let e = optimal_estimate(&existence, metric, c, p).unwrap();
            optimal.push(
                json!({"existence": existence, "metric": name, "c": c, "p": p,
                "expected": {"report": e.report, "meanSquareError": e.mean_square_error}}),
            );
        }
    }
    json!({
        "about": "Seeded inputs and native outputs; see tests/tests/parity.rs. Regenerate with FISST_BLESS=1.",
        "gospa": gospa, "ospa": ospa, "cardinality": cardinality, "optimal": optimal
    })
}

#[test]
fn native_outputs_match_the_parity_fixture() {
    let path = data_path("parity.json");
    let fresh = build();
    if std::env::var_os("FISST_BLESS").is_some() {
        std::fs::write(&path, serde_json::to_string_pretty(&fresh).unwrap() + "\n").unwrap();
    }
    let stored: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    // With `float_roundtrip`, serde_json reads back exactly the f64 it wrote (shortest
    // representation), so equality is bitwise.
    if let Some(path) = first_difference(&stored, &fresh, String::new()) {
        panic!("native outputs drifted from tests/data/parity.json at {path}");
    }
}

fn first_difference(a: &Value, b: &Value, path: String) -> Option<String> {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            if x.len() != y.len() {
                return Some(path);
            }
            x.iter().find_map(|(k, v)| match y.get(k) {
                Some(w) => first_difference(v, w, format!("{path}.{k}")),
                None => Some(format!("{path}.{k}")),
            })
        }
        (Value::Array(x), Value::Array(y)) => {
            if x.len() != y.len() {
                return Some(format!("{path} (length)"));
            }
            x.iter()
                .zip(y)
                .enumerate()
                .find_map(|(i, (v, w))| first_difference(v, w, format!("{path}[{i}]")))
        }
        _ if a == b => None,
        _ => Some(format!("{path}: {a} vs {b}")),
    }
}
