//! Tests of the TypeScript generator of `build.rs` (`wasm/tsgen.rs`), on Rust source written
//! here: what a core type's declaration looks like in JavaScript names. Native:
//! `cargo test -p fisst-wasm --test tsgen`.

#[path = "../src/names_rule.rs"]
#[allow(dead_code)]
mod names_rule;
#[path = "../tsgen.rs"]
#[allow(dead_code)]
mod tsgen;

use std::collections::BTreeMap;
use std::string::{String, ToString};

const SOURCE: &str = r#"
/// Options of a filter.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FilterOptions {
    /// The cut-off [`Gospa`] uses, c > 0.
    pub c: f64,
    /// The order (default 2).
    #[cfg_attr(feature = "serde", serde(default = "FilterOptions::default_p"))]
    pub p: f64,
    /// Scans ahead (with `transition.survival_probability`; see `shape[i].max_corner`,
    /// `Transition::survival_probability`, `MAX_DENSE_WORK` and `a_b + c`; eq. (3) of
    /// `001_0f0df91eee9b30d5.txt`); `None`: no limit. Or `{ future_scans: { max_corner },
    /// b: a_b }`.
    pub future_scans: Option<usize>,
    pub transition: Transition,
    pub pairs: Vec<(usize, usize)>,
    pub shape: Shape,
}
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Transition {
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::matrix"))]
    pub f: DMatrix<f64>,
    pub survival_probability: f64,
}
/// A region.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "camelCase"))]
pub enum Shape {
    BoxRegion { min: Vec<f64>, max_corner: Vec<f64> },
    Disc(f64),
    Everywhere,
}
pub struct NotSerde { pub x: f64 }
"#;

fn declarations(roots: &[&str]) -> (String, std::vec::Vec<String>) {
    declarations_in(SOURCE, roots)
}

/// What `tsgen::declarations` declares of the items of `source` for `roots`, and its warnings.
fn declarations_in(source: &str, roots: &[&str]) -> (String, std::vec::Vec<String>) {
    let mut defs = BTreeMap::new();
    tsgen::walk(syn::parse_file(source).unwrap().items, &mut defs);
    let roots: std::vec::Vec<String> = roots.iter().map(|r| r.to_string()).collect();
    let refs: std::vec::Vec<&String> = roots.iter().collect();
    tsgen::declarations(&defs, &refs)
}

#[test]
fn a_struct_is_an_interface_in_javascript_names_with_its_docs() {
    let (ts, warnings) = declarations(&["FilterOptions"]);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "/**\n * Options of a filter.\n */\nexport interface FilterOptions {",
        "     * The cut-off `Gospa` uses, c > 0.\n",
        "    c: number;",
        "    p?: number;",
        "    futureScans?: number;",
        "    transition: Transition;",
        "    pairs: [number, number][];",
        "export interface Transition {",
        // the matrix keeps its capital under `transition`, and is rows of numbers
        "    F: number[][];",
        "    survivalProbability: number;",
        "    | { boxRegion: {",
        "        maxCorner: number[];",
        "    | { disc: number }",
        "    | \"everywhere\";",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
}

#[test]
fn only_the_roots_and_what_they_hold_are_declared() {
    let (ts, _) = declarations(&["Shape"]);
    assert!(ts.contains("export type Shape ="));
    assert!(!ts.contains("FilterOptions"));
    assert!(!ts.contains("Transition"));
    assert!(!ts.contains("NotSerde"));
}

#[test]
fn a_type_that_is_not_a_serde_type_is_a_warning_not_a_guess() {
    let source = "#[cfg_attr(feature = \"serde\", derive(serde::Serialize))] pub struct A { pub b: NotSerde }";
    let (ts, warnings) = declarations_in(source, &["A"]);
    assert!(ts.contains("b: unknown;"));
    assert_eq!(warnings.len(), 1, "{warnings:?}");
}

#[test]
fn arrays_are_tuples_aliases_inline_skipped_fields_absent_and_number_lists_typed_arrays() {
    let source = r#"
pub type State = [f64; 2];
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Run {
    pub start: State,
    pub path: Vec<[f64; 2]>,
    pub big: [f64; 17],
    #[cfg_attr(feature = "serde", serde(skip))]
    pub inside: bool,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub clutter_density: Vec<f64>,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::rows_of_numbers"))]
    pub likelihoods: Vec<Vec<f64>>,
}
"#;
    let (ts, warnings) = declarations_in(source, &["Run"]);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "    start: [number, number];",
        "    path: [number, number][];",
        "    big: number[];",
        "    clutterDensity: number[] | Float64Array;",
        "    likelihoods: (number[] | Float64Array)[];",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
    assert!(!ts.contains("inside"), "{ts}");
    assert!(!ts.contains("State"), "{ts}");
}

const SHAPES: &str = r#"
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "kebab-case"))]
pub enum Method {
    Mam,
    MapCardinality,
    #[cfg_attr(feature = "serde", serde(untagged))]
    Weighted { weight: f64 },
}
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Inputs {
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::numbers"))]
    pub existence: Vec<f64>,
    #[cfg_attr(feature = "serde", serde(default, with = "crate::serde_shapes::numbers"))]
    pub ln_peak: Option<Vec<f64>>,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::point_sets"))]
    pub truths: Vec<Vec<Vec<f64>>>,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::bytes"))]
    pub decisions: Vec<u8>,
    pub method: Method,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::nullable"))]
    pub estimate: Option<Vec<f64>>,
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub split: GaussianMixture,
    pub true_reports: Vec<Option<usize>>,
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::serde_shapes::numbers::serialize"))]
    pub knots: Vec<f64>,
}
"#;

#[test]
fn kebab_case_variants_and_the_number_shapes_of_serde_shapes() {
    let (ts, warnings) = declarations_in(SHAPES, &["Inputs"]);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "    existence: number[] | Float64Array;",
        "    lnPeak?: number[] | Float64Array;",
        "    truths: (number[] | Float64Array)[][];",
        "    decisions: Uint8Array;",
        // a nullable Option is always present, null for None
        "    estimate: number[] | null;",
        // a result's mixture, as the binding declares it
        "    split: MixtureComponent[];",
        // an Option in an array is written null for None
        "    trueReports: (number | null)[];",
        // marked by the module's `serialize` alone (read as a plain `Vec`)
        "    knots: number[] | Float64Array;",
        "    | \"mam\"",
        "    | \"map-cardinality\"",
        // an untagged variant is its body alone
        "    | {\n        weight: number;\n    };",
    ] {
        assert!(ts.contains(expected), "{expected:?} not in\n{ts}");
    }
}

#[test]
fn an_item_is_compiled_for_a_part_when_its_cfg_holds() {
    let on = |f: &str| f == "metrics";
    let holds = |src: &str| {
        let item: syn::Item = syn::parse_str(src).unwrap();
        tsgen::cfg_enabled(tsgen::item_attrs(&item), &on)
    };
    assert!(holds("mod a;"));
    assert!(holds("#[cfg(feature = \"metrics\")] mod a;"));
    assert!(!holds("#[cfg(feature = \"control\")] mod a;"));
    // `any`/`all`/`not` (the old reading took `cfg(any(…))` for "always")
    assert!(!holds(
        "#[cfg(any(feature = \"bernoulli\", feature = \"splitting\"))] mod fov;"
    ));
    assert!(holds(
        "#[cfg(any(feature = \"bernoulli\", feature = \"metrics\"))] fn f() {}"
    ));
    assert!(!holds(
        "#[cfg(all(feature = \"bernoulli\", feature = \"metrics\"))] fn f() {}"
    ));
    assert!(holds("#[cfg(not(feature = \"control\"))] const C: u8 = 0;"));
    // a build script is not a test build
    assert!(!holds("#[cfg(test)] mod tests;"));
    // a macro call that writes exports (`filter_methods!(…)`), with its `#[cfg]`
    assert!(!holds("#[cfg(feature = \"control\")] m!(A, \"A\");"));
    assert!(holds("#[cfg(feature = \"metrics\")] m!(A, \"A\");"));
}

#[test]
fn a_hand_written_impl_is_declared_by_the_form_renamed_to_it() {
    // the core's pattern: a type (no derive) read and written through a derived form
    let source = r#"
pub enum Density { Gaussian { mean: f64, variance: f64 }, Table(Vec<f64>) }
/// A 1D density as read and written.
#[derive(Serialize, Deserialize)]
#[serde(rename = "Density", rename_all = "camelCase")]
enum DensityRepr { Gaussian { mean: f64, variance: f64 }, Table { x: Vec<f64> } }
/// Another type's form, not renamed to a type: only its own name.
#[derive(Serialize, Deserialize)]
struct PlainRepr { low: f64 }
/// A derived type keeps its own declaration against a form renamed to its name.
#[derive(Serialize, Deserialize)]
pub struct Kept { kept: f64 }
#[derive(Serialize, Deserialize)]
#[serde(rename = "Kept")]
struct KeptRepr { other: f64 }
"#;
    let mut defs = BTreeMap::new();
    tsgen::walk(syn::parse_file(source).unwrap().items, &mut defs);
    let roots = ["Density".to_string(), "Kept".to_string()];
    let refs: std::vec::Vec<&String> = roots.iter().collect();
    let (ts, warnings) = tsgen::declarations(&defs, &refs);
    assert!(warnings.is_empty(), "{warnings:?}");
    assert!(ts.contains("export type Density =\n"), "{ts}");
    assert!(ts.contains("| { gaussian: {\n"), "{ts}");
    assert!(ts.contains("| { table: {\n"), "{ts}");
    assert!(ts.contains("    kept: number;"), "{ts}");
    assert!(!ts.contains("other"), "{ts}");
    assert!(defs.contains_key("PlainRepr") && !defs.contains_key("Plain"));
}

#[test]
fn a_type_written_through_a_form_is_declared_by_it_or_by_the_core_type_it_is_renamed_to() {
    // `through_constructor!(Type, Form, …)`: `Type` (no derive) is written as `Form`; a form
    // renamed to another core type is written as that type, and named by it
    let source = r#"
pub struct Transition { f: DMatrix<f64> }
#[derive(Serialize, Deserialize)]
pub struct TransitionRows { #[serde(rename = "F")] pub f: Vec<Vec<f64>> }
#[derive(Serialize, Deserialize)]
#[serde(rename = "TransitionRows")]
struct TransitionRepr { #[serde(with = "matrix")] f: DMatrix<f64> }
through_constructor!(Transition, TransitionRepr, |t| TransitionRepr { f: t.f.clone() }, |r| Ok(r));
pub struct Prior { m: f64 }
/// A prior as written.
#[derive(Serialize, Deserialize)]
struct PriorRepr { mean: f64 }
through_constructor!(Prior, PriorRepr, |p| PriorRepr { mean: p.m }, |r| Ok(r), below "prior");
#[derive(Serialize, Deserialize)]
pub struct Model { pub transition: Transition, pub prior: Prior }
"#;
    let (ts, warnings) = declarations_in(source, &["Model"]);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "    transition: TransitionRows;",
        "export interface TransitionRows {\n    F: number[][];\n}",
        "    prior: Prior;",
        "/**\n * A prior as written.\n */\nexport interface Prior {\n    mean: number;\n}",
    ] {
        assert!(ts.contains(expected), "{expected:?} not in\n{ts}");
    }
    assert!(!ts.contains("Repr"), "{ts}");
}

#[test]
fn scalar_or_is_a_number_or_an_array_and_a_declared_name_wins_over_a_core_alias() {
    let src = r#"
pub type Covariance = ScalarOr<ScalarOr<f64>>;
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Observation {
    pub gain: Option<ScalarOr<Vec<f64>>>,
    pub offset: ScalarOr<f64>,
    pub noise_cov: Covariance,
    pub gains: ScalarOr<Gain>,
}
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Gain { pub a: f64 }
"#;
    let mut defs = BTreeMap::new();
    tsgen::walk(syn::parse_file(src).unwrap().items, &mut defs);
    let root = "Observation".to_string();
    let declared = ["Covariance".to_string()].into_iter().collect();
    let (ts, warnings) = tsgen::declarations_with(&defs, &[&root], &declared);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "    gain?: number | (number[] | Float64Array)[];",
        "    offset: number | number[] | Float64Array;",
        // the binding declares `Covariance` itself: named, not inlined from the core's alias
        "    noiseCov: Covariance;",
        "    gains: number | Gain[];",
        "export interface Gain {",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
}

#[test]
fn field_paths_quoted_in_docs_are_in_javascript_names() {
    let (ts, _) = declarations(&["FilterOptions"]);
    assert!(
        ts.contains(
            "Scans ahead (with `transition.survivalProbability`; see `shape[i].maxCorner`,\n"
        ),
        "{ts}"
    );
    // Rust paths, constants and expressions stay as written
    assert!(
        ts.contains(
            "`Transition::survival_probability`, `MAX_DENSE_WORK` and `a_b + c`; eq. (3) of"
        ),
        "{ts}"
    );
    // a file name is not a path: its segments are not identifiers
    assert!(
        ts.contains("`001_0f0df91eee9b30d5.txt`); `null`: no limit."),
        "{ts}"
    );
    // the keys of an object are renamed, the names it holds as values are not
    assert!(
        ts.contains("Or `{ futureScans: { max_corner },\n     * b: a_b }`."),
        "{ts}"
    );
}

#[test]
fn an_alias_of_ts_aliases_is_declared_where_the_part_reaches_one_of_its_names() {
    let mut defs = BTreeMap::new();
    tsgen::walk(syn::parse_file(SOURCE).unwrap().items, &mut defs);
    let table = [
        // reached by a root: the core type it names is generated
        ("FilterResult", "FilterOptions", "Result of `filter`"),
        // reached through the generated types (`FilterOptions.shape`)
        ("ShapeOut", "Shape", "A shape.\nOn two lines."),
        // a binding's name the generated types hold (`transition: Transition`)
        ("Transition", "TransitionShape", "The core's `Transition`."),
        // not reached: left out
        ("Other", "NotSerde", "Another"),
    ];
    let set = |names: &[&str]| names.iter().map(|n| n.to_string()).collect();
    let declared = set(&["FilterResult", "ShapeOut", "Transition", "Other"]);
    let (ts, warnings) =
        tsgen::part_declarations(&defs, &set(&["FilterResult"]), &set(&[]), &declared, &table);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "/**\n * Result of `filter`: the core's `FilterOptions`.\n */\nexport type FilterResult = FilterOptions;\n",
        "/**\n * A shape.\n * On two lines.\n */\nexport type ShapeOut = Shape;\n",
        "export type Transition = TransitionShape;\n",
        "export interface FilterOptions {",
        "    transition: Transition;",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
    assert!(!ts.contains("Other"), "{ts}");
    // a name the part's own TypeScript holds reaches the alias too, the type it names does not
    let (ts, _) =
        tsgen::part_declarations(&defs, &set(&[]), &set(&["NotSerde"]), &declared, &table);
    assert!(ts.is_empty(), "{ts}");
    let (ts, _) = tsgen::part_declarations(&defs, &set(&[]), &set(&["Other"]), &declared, &table);
    assert!(
        ts.starts_with(
            "/**\n * Another: the core's `NotSerde`.\n */\nexport type Other = NotSerde;\n"
        ),
        "{ts}"
    );
}

#[test]
fn variant_tags_in_javascript_names_a_bare_variant_and_a_form_named_by_its_rename() {
    // the core's `Region`: read through a form renamed to it, whose variants hold forms
    // renamed to the contract's names; `ball` is JavaScript's `disc`, a polygon is given bare
    let source = r#"
pub struct Region { node: Node }
#[derive(Serialize)]
#[serde(rename = "Region", rename_all = "snake_case")]
enum RegionRef<'a> { Box(&'a AxisBox), Ball(&'a Ball) }
/// A region.
#[derive(Deserialize)]
#[serde(rename = "Region")]
enum RegionRepr {
    #[serde(rename = "box")]
    Box(AxisBoxRepr),
    #[serde(rename = "polygon")]
    Polygon(PolygonRepr),
    #[serde(rename = "ball")]
    Ball(BallRepr),
    #[serde(rename = "union")]
    Union(Vec<Region>),
}
#[derive(Serialize, Deserialize)]
#[serde(rename = "BoxRegion")]
struct AxisBoxRepr { #[serde(with = "crate::serde_shapes::numbers")] min: Vec<f64> }
#[derive(Serialize, Deserialize)]
#[serde(rename = "DiscRegion")]
struct BallRepr { radius: f64 }
#[derive(Serialize, Deserialize)]
struct PolygonRepr { vertices: Vec<[f64; 2]> }
#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
enum Density {
    MultiBernoulli(#[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::bernoullis"))] Vec<(f64, G)>),
    IidCluster { size_hint: f64 },
}
"#;
    let (ts, warnings) = declarations_in(source, &["Region", "Density"]);
    assert!(warnings.is_empty(), "{warnings:?}");
    for expected in [
        "/**\n * A region.\n */\nexport type Region =\n",
        "    | { box: BoxRegion }",
        "    | { polygon: [number, number][] }",
        "    | { disc: DiscRegion }",
        "    | { union: Region[] }",
        "export interface BoxRegion {\n    min: number[] | Float64Array;\n}",
        "export interface DiscRegion {\n    radius: number;\n}",
        // a `with` on the variant's field
        "    | { multiBernoulli: Bernoulli[] }",
        "    | { iidCluster: {\n        sizeHint: number;\n",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
    assert!(!ts.contains("Repr") && !ts.contains("ball"), "{ts}");
}

#[test]
fn asides_for_rust_readers_only_are_left_out() {
    let source = r#"
/// The options of a split ([`SplitOptions::split`]), its caps (see
/// [`crate::MAX_DEPTH`] / [`crate::MAX_COMPONENTS`]) and its library (`lambda`), at most 16
/// levels deep ([`MAX_LEVELS`]) and 100 wide (`MAX_WIDTH`: a constant; `NOT_ONE`).
/// (In Rust, [`SplitOptions::build`] checks them and makes the `Split`.)
///
/// ([`Split::new`] and [`Split::run`]) A new paragraph.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SplitOptions {
    /// A constant or one value per report (in Rust, also a function; see
    /// [`Density::Function`]), e.g. `f(x)` (as in [`Density::eval`], not a Rust aside).
    ///
    /// (In Rust, a paragraph of its own.)
    pub density_value: f64,
}
"#;
    let (ts, _) = declarations_in(source, &["SplitOptions"]);
    for expected in [
        // a parenthetical of Rust items alone goes, with the spaces and line break before it
        " * The options of a split, its caps and its library (`lambda`), at most 16\n",
        // a constant is a Rust item too, alone; said with more it stays
        " * levels deep and 100 wide (`MAX_WIDTH`: a constant; `NOT_ONE`).\n",
        // one that starts "in Rust" goes, whatever it holds
        "`NOT_ONE`).\n *\n",
        // a paragraph keeps its break
        " *\n * A new paragraph.\n",
        // joined to the line after it; a parenthetical that also says more stays
        "A constant or one value per report, e.g. `f(x)` (as in `Density::eval`, not a Rust aside).\n",
        // a paragraph dropped at the end leaves no empty line
        "not a Rust aside).\n     */\n",
    ] {
        assert!(ts.contains(expected), "missing {expected:?} in\n{ts}");
    }
    assert!(!ts.contains("In Rust") && !ts.contains("::build"), "{ts}");
}
