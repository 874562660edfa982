//! Python's names for the core's Rust names: the Rust names themselves (snake_case), except
//! the matrices of a linear-Gaussian transition and measurement model, which keep the
//! papers' capitals (`transition.F`, `likelihood.H`): the same exceptions as the JavaScript
//! binding, from its one table.

#[path = "../../wasm/src/names_rule.rs"]
#[allow(dead_code)]
pub(crate) mod rule;

/// An error path in Rust names (`transition.f`, `components[2].mean`) in Python's names
/// (`transition.F`, `components[2].mean`).
pub fn render_path(rust_path: &str) -> String {
    let mut out = String::with_capacity(rust_path.len());
    let mut parent = "";
    for (i, segment) in rust_path.split('.').enumerate() {
        if i > 0 {
            out.push('.');
        }
        let (name, indices) = segment.split_at(segment.find('[').unwrap_or(segment.len()));
        match rule::EXCEPTIONS
            .iter()
            .find(|(p, f, _)| *p == parent && *f == name)
        {
            Some((_, _, matrix)) => out.push_str(matrix),
            None => out.push_str(name),
        }
        out.push_str(indices);
        parent = name;
    }
    out
}
