//! The TypeScript generator of `build.rs` (see there): reads Rust source with `syn` and writes
//! declarations of the serde types in JavaScript names. Tested in `tests/tsgen.rs`.

use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::fs;
use std::path::Path;

use syn::punctuated::Punctuated;

use super::names_rule;
use syn::{Attribute, Expr, Fields, GenericArgument, Item, Lit, Meta, PathArguments, Token, Type};

#[derive(Default, Debug, Clone)]
pub struct Serde {
    derive: bool,
    /// Derives `Deserialize` (a form read from JavaScript, preferred for a renamed name).
    deserialize: bool,
    default: bool,
    rename: Option<String>,
    rename_all: Option<String>,
    optional_out: bool,
    with: Option<String>,
    try_from: Option<String>,
    tag: Option<String>,
    untagged: bool,
    transparent: bool,
    skip: bool,
}

fn lit_str(e: &Expr) -> Option<String> {
    if let Expr::Lit(l) = e
        && let Lit::Str(s) = &l.lit
    {
        return Some(s.value());
    }
    None
}

fn read_serde_list(list: &syn::MetaList, s: &mut Serde) {
    let Ok(items) = list.parse_args_with(Punctuated::<Meta, Token![,]>::parse_terminated) else {
        return;
    };
    for m in items {
        let name = m
            .path()
            .get_ident()
            .map(|i| i.to_string())
            .unwrap_or_default();
        match (&*name, &m) {
            ("default", _) => s.default = true,
            ("untagged", _) => s.untagged = true,
            ("transparent", _) => s.transparent = true,
            ("skip", _) => s.skip = true,
            ("rename", Meta::NameValue(nv)) => s.rename = lit_str(&nv.value),
            ("rename_all", Meta::NameValue(nv)) => s.rename_all = lit_str(&nv.value),
            ("skip_serializing_if", _) => s.optional_out = true,
            ("with" | "serialize_with" | "deserialize_with", Meta::NameValue(nv)) => {
                s.with = lit_str(&nv.value)
            }
            ("try_from" | "from", Meta::NameValue(nv)) => s.try_from = lit_str(&nv.value),
            ("tag", Meta::NameValue(nv)) => s.tag = lit_str(&nv.value),
            _ => {}
        }
    }
}

pub fn serde_of(attrs: &[Attribute]) -> Serde {
    let mut s = Serde::default();
    for a in attrs {
        if a.path().is_ident("serde") {
            if let Meta::List(l) = &a.meta {
                read_serde_list(l, &mut s);
            }
        } else if a.path().is_ident("derive") {
            let t = a.meta.to_token_stream_string();
            s.derive |= t.contains("Serialize") || t.contains("Deserialize");
            s.deserialize |= t.contains("Deserialize");
        } else if a.path().is_ident("cfg_attr") {
            let Ok(items) = a.parse_args_with(Punctuated::<Meta, Token![,]>::parse_terminated)
            else {
                continue;
            };
            let mut it = items.iter();
            let cond = it
                .next()
                .map(|m| m.to_token_stream_string())
                .unwrap_or_default();
            if !cond.contains("serde") {
                continue;
            }
            for m in it {
                if let Meta::List(l) = m {
                    if l.path.is_ident("serde") {
                        read_serde_list(l, &mut s);
                    } else if l.path.is_ident("derive") {
                        let t = l.tokens.to_string();
                        s.derive |= t.contains("Serialize") || t.contains("Deserialize");
                        s.deserialize |= t.contains("Deserialize");
                    }
                }
            }
        }
    }
    s
}

pub trait TokStr {
    fn to_token_stream_string(&self) -> String;
}
impl<T: quote::ToTokens> TokStr for T {
    fn to_token_stream_string(&self) -> String {
        self.to_token_stream().to_string()
    }
}

fn docs(attrs: &[Attribute]) -> Vec<String> {
    let lines: Vec<String> = attrs
        .iter()
        .filter(|a| a.path().is_ident("doc"))
        .filter_map(|a| match &a.meta {
            Meta::NameValue(nv) => lit_str(&nv.value),
            _ => None,
        })
        .map(|s| strip_links(s.strip_prefix(' ').unwrap_or(&s)))
        .collect();
    if lines.is_empty() {
        return lines;
    }
    // joined, as an aside may run over lines; a paragraph dropped at the end leaves no blank
    drop_rust_asides(&lines.join("\n"))
        .trim_end()
        .split('\n')
        .map(js_code_spans)
        .collect()
}

/// A doc without its asides for Rust readers only, which a JavaScript reader cannot use: a
/// parenthetical that only names Rust items (code spans holding `::` or naming a constant,
/// `MAX_GAUSSIANS`, joined by `,`, `/`,
/// `and`, `or`, after an optional "see": "(`LikelihoodRows::build`)", "(see
/// `SpatialDensity::mmuc`)"), and one that starts "in Rust" (the convention for anything else
/// only Rust has: "(in Rust, also a function)", "(In Rust, `X::build` makes it.)"). The
/// spaces before an aside go with it.
fn drop_rust_asides(doc: &str) -> String {
    let mut doc = doc.to_string();
    'scan: loop {
        let (mut opens, mut code) = (Vec::new(), false);
        for (i, c) in doc.char_indices() {
            match c {
                '`' => code = !code,
                '(' if !code => opens.push(i),
                ')' if !code => {
                    let Some(open) = opens.pop() else { continue };
                    if !rust_only(&doc[open + 1..i]) {
                        continue;
                    }
                    // the spaces before, and a line break (not a paragraph's)
                    let mut before = doc[..open].trim_end_matches(' ');
                    if before.ends_with('\n') && !before.ends_with("\n\n") && before.len() > 1 {
                        before = &before[..before.len() - 1];
                    }
                    let after = match before.is_empty() || before.ends_with('\n') {
                        true => doc[i + 1..].trim_start_matches(' '),
                        false => &doc[i + 1..],
                    };
                    doc = format!("{before}{after}");
                    continue 'scan;
                }
                _ => {}
            }
        }
        return doc;
    }
}

/// A Rust constant's name (`MAX_GAUSSIANS`): capitals, digits and at least one `_`.
fn is_rust_constant(code: &str) -> bool {
    code.contains('_')
        && code
            .chars()
            .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
}

/// Whether the text of a parenthetical is for Rust readers only (see [`drop_rust_asides`]).
fn rust_only(aside: &str) -> bool {
    let aside = aside.trim();
    if aside.to_lowercase().starts_with("in rust") {
        return true;
    }
    let parts: Vec<&str> = aside.split('`').collect();
    parts.len() >= 3
        && parts.len() % 2 == 1
        && parts.iter().enumerate().all(|(i, p)| match (i, p.trim()) {
            (_, code) if i % 2 == 1 => code.contains("::") || is_rust_constant(code),
            (0, "see") => true,
            (_, text) => matches!(text, "" | "," | "/" | "and" | "or" | ", and" | ", or"),
        })
}

/// The Rust field paths quoted in a doc line under their JavaScript names, as the declarations
/// show the fields: "`prior.multivariate_gaussian.mean`" → "`prior.multivariateGaussian.mean`",
/// "`quadrature_cardinality`" → "`quadratureCardinality`". Only code spans that are a plain
/// path (identifiers, dots, `[i]`) change; Rust paths (`a::b`) and expressions stay; `None`
/// is said as JavaScript says it, `null`.
fn js_code_spans(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    for (i, part) in line.split('`').enumerate() {
        if i > 0 {
            out.push('`');
        }
        // lower-case names only: a constant (`MAX_DENSE_WORK`) stays as it is, and so does a
        // file name (`001_0f0df91eee9b30d5.txt`: a segment that does not start as a name)
        let plain_path = part.contains('_')
            && part.chars().all(|c| {
                c.is_ascii_lowercase() || c.is_ascii_digit() || matches!(c, '_' | '.' | '[' | ']')
            })
            && part
                .split('.')
                .all(|seg| seg.starts_with(|c: char| c.is_ascii_lowercase() || c == '_'));
        if i % 2 == 1 && part == "None" {
            // an absent value, as the bindings write it
            out.push_str("null");
        } else if i % 2 == 1 && part.starts_with('{') {
            out.push_str(&js_keys(part));
        } else if i % 2 == 1 && plain_path {
            let mut parent = "";
            let renamed: Vec<_> = part
                .split('.')
                .map(|seg| {
                    let (name, index) = seg.split_at(seg.find('[').unwrap_or(seg.len()));
                    let js = format!("{}{index}", names_rule::js_name_of(parent, name));
                    parent = name;
                    js
                })
                .collect();
            out.push_str(&renamed.join("."));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// An object written in a doc's code span with its keys in JavaScript names: "`{
/// multivariate_gaussian: { mean, cov } }`" → "`{ multivariateGaussian: { mean, cov } }`"
/// (a name followed by `:`).
fn js_keys(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut rest = code;
    while let Some(start) = rest.find(|c: char| c.is_ascii_lowercase() || c == '_') {
        let len = rest[start..]
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len() - start);
        let (word, after) = rest[start..].split_at(len);
        out.push_str(&rest[..start]);
        match after.trim_start().starts_with(':') {
            true => out.push_str(&names_rule::js_name_of("", word)),
            false => out.push_str(word),
        }
        rest = after;
    }
    out + rest
}

/// Rustdoc's intra-doc links as plain code: "[`X`]" and "[`x`](path)" become "`X`", "`x`".
fn strip_links(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(start) = rest.find("[`") {
        let Some(end) = rest[start..].find("`]").map(|e| start + e) else {
            break;
        };
        out.push_str(&rest[..start]);
        out.push_str(&rest[start + 1..=end]);
        rest = &rest[end + 2..];
        // a link target in parentheses goes too
        if rest.starts_with('(')
            && let Some(close) = rest.find(')')
        {
            rest = &rest[close + 1..];
        }
    }
    out.push_str(rest);
    out
}

pub struct Def {
    item: Item,
}

pub fn collect(dir: &Path, out: &mut BTreeMap<String, Def>) {
    for e in fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let f = syn::parse_file(&fs::read_to_string(&p).unwrap()).unwrap();
            walk(f.items, out);
        }
    }
}

/// Registers the serde types of `items` by their Rust names. A type with a hand-written serde
/// impl has no derive to read; when the impl goes through a derived form renamed to it
/// (`#[serde(rename = "Density1")] enum Density1Repr`), the form is also registered under that
/// name, which is how the type is written; of two forms renamed to one name (a type's
/// `Serialize` form and its `Deserialize` form), the one read from JavaScript. A type written
/// through a form by `through_constructor!(Type, Form, …)` is registered as its form.
pub fn walk(items: Vec<Item>, out: &mut BTreeMap<String, Def>) {
    let mut forms = Vec::new();
    let mut constructed = Vec::new();
    for it in items {
        match &it {
            Item::Macro(m) if m.mac.path.is_ident("through_constructor") => {
                let args = m.mac.tokens.to_string();
                let mut names = args.split(',').map(str::trim);
                if let (Some(ty), Some(form)) = (names.next(), names.next()) {
                    constructed.push((ty.to_string(), form.to_string()));
                }
            }
            Item::Struct(s) if serde_of(&s.attrs).derive => {
                forms.extend(serde_of(&s.attrs).rename.map(|r| (r, it.clone())));
                out.insert(s.ident.to_string(), Def { item: it.clone() });
            }
            Item::Enum(e) if serde_of(&e.attrs).derive => {
                forms.extend(serde_of(&e.attrs).rename.map(|r| (r, it.clone())));
                out.insert(e.ident.to_string(), Def { item: it.clone() });
            }
            // a plain alias (`pub type State = [f64; 2];`), written inline where it is used
            Item::Type(t) if t.generics.params.is_empty() => {
                out.entry(t.ident.to_string())
                    .or_insert(Def { item: it.clone() });
            }
            Item::Mod(m) => {
                if let Some((_, inner)) = &m.content {
                    walk(inner.clone(), out);
                }
            }
            _ => {}
        }
    }
    forms.sort_by_key(|(_, item)| !serde_of(item_attrs(item)).deserialize);
    for (name, item) in forms {
        out.entry(name).or_insert(Def { item });
    }
    for (ty, form) in constructed {
        if let Some(item) = out.get(&form).map(|d| d.item.clone()) {
            out.entry(ty).or_insert(Def { item });
        }
    }
}

/// The length of an array type `[T; N]` written as a tuple: a literal N of at most 16.
fn tuple_len(len: &Expr) -> Option<usize> {
    match len {
        Expr::Lit(l) => match &l.lit {
            Lit::Int(n) => n.base10_parse().ok().filter(|&n| n <= 16),
            _ => None,
        },
        _ => None,
    }
}

fn rename_variant(v: &str, rule: Option<&str>) -> String {
    match rule {
        Some("lowercase") => v.to_lowercase(),
        Some("camelCase") => {
            let mut c = v.chars();
            c.next()
                .map(|f| f.to_lowercase().collect::<String>() + c.as_str())
                .unwrap_or_default()
        }
        Some(rule @ ("snake_case" | "kebab-case")) => {
            let sep = if rule == "snake_case" { '_' } else { '-' };
            let mut s = String::new();
            for (i, ch) in v.chars().enumerate() {
                if ch.is_uppercase() && i > 0 {
                    s.push(sep);
                }
                s.extend(ch.to_lowercase());
            }
            s
        }
        _ => v.to_string(),
    }
}

pub struct Gen<'a> {
    pub defs: &'a BTreeMap<String, Def>,
    pub queue: VecDeque<String>,
    pub seen: BTreeSet<String>,
    pub warnings: Vec<String>,
    /// The field being typed (the parent of the types it names).
    pub holder: String,
    /// The fields each type is held in, which decide its fields' JavaScript names.
    pub parents: BTreeMap<String, BTreeSet<String>>,
    /// Core types whose TypeScript the binding declares itself under the same name (a core
    /// type with a hand-written serde form, such as `Costs`): named, not generated.
    pub declared: &'a BTreeSet<String>,
    /// The declared names the generated types hold.
    pub named: BTreeSet<String>,
}

impl Gen<'_> {
    pub fn want(&mut self, name: &str) {
        self.parents
            .entry(name.to_string())
            .or_default()
            .insert(self.holder.clone());
        if self.seen.insert(name.to_string()) {
            self.queue.push_back(name.to_string());
        }
    }

    /// The JavaScript name of the field `field` of the type `owner`.
    fn field_name(&self, owner: &str, field: &str) -> String {
        let parents = self.parents.get(owner).cloned().unwrap_or_default();
        parents
            .iter()
            .map(|p| names_rule::js_name_of(p, field))
            .find(|js| *js != names_rule::camel_case(field))
            .unwrap_or_else(|| names_rule::camel_case(field).into_owned())
    }

    fn ty(&mut self, t: &Type, with: Option<&str>) -> String {
        if let Some(w) = with {
            // a module's `serialize` alone (`serialize_with`) marks the field as the module
            // does, leaving how it is read alone
            let mut segments = w.rsplit("::").skip_while(|s| *s == "serialize");
            let last = segments.next().unwrap_or(w);
            return match last {
                "matrix" => "number[][]".into(),
                "vector" | "numbers" => "number[] | Float64Array".into(),
                "rows_of_numbers" => "(number[] | Float64Array)[]".into(),
                "point_sets" => "(number[] | Float64Array)[][]".into(),
                // `[{ existence, mean, cov }, …]`, declared by the binding
                "bernoullis" => "Bernoulli[]".into(),
                // a result's mixture (`cov` as rows), declared by the binding
                "components" => "MixtureComponent[]".into(),
                // `[{ weight, components }, …]`, declared by the binding
                "glmb_hypotheses" => "GlmbHypothesis[]".into(),
                "bytes" => "Uint8Array".into(),
                other => {
                    self.warnings.push(format!("unknown `with` module {other}"));
                    "unknown".into()
                }
            };
        }
        match t {
            Type::Reference(r) => self.ty(&r.elem, None),
            // `[T; N]` is a tuple of N (as tsify writes it), for the small N of points
            Type::Array(a) => match tuple_len(&a.len) {
                Some(n) => {
                    let one = self.ty(&a.elem, None);
                    format!("[{}]", vec![one; n].join(", "))
                }
                None => format!("{}[]", self.ty_paren(&a.elem)),
            },
            Type::Slice(a) => format!("{}[]", self.ty_paren(&a.elem)),
            Type::Tuple(tp) => {
                let parts: Vec<String> = tp.elems.iter().map(|e| self.ty(e, None)).collect();
                format!("[{}]", parts.join(", "))
            }
            Type::Path(p) => {
                let seg = p.path.segments.last().unwrap();
                let name = seg.ident.to_string();
                let args: Vec<Type> = match &seg.arguments {
                    PathArguments::AngleBracketed(a) => a
                        .args
                        .iter()
                        .filter_map(|g| {
                            if let GenericArgument::Type(t) = g {
                                Some(t.clone())
                            } else {
                                None
                            }
                        })
                        .collect(),
                    _ => vec![],
                };
                match &*name {
                    "f64" | "f32" | "usize" | "u8" | "u16" | "u32" | "u64" | "i8" | "i16"
                    | "i32" | "i64" | "isize" => "number".into(),
                    "bool" => "boolean".into(),
                    "String" | "str" => "string".into(),
                    "Vec" | "VecDeque" | "Box" if !args.is_empty() => {
                        if name == "Box" {
                            self.ty(&args[0], None)
                        } else {
                            format!("{}[]", self.ty_paren(&args[0]))
                        }
                    }
                    // an `Option` held by another type (an array's entry; a field's is optional
                    // instead, see `fields`): the bindings write `None` as null (and read null
                    // or undefined)
                    "Option" => format!("{} | null", self.ty(&args[0], None)),
                    // one number, or an array of `T` (numbers may be a `Float64Array`)
                    "ScalarOr" => match &*self.ty(&args[0], None) {
                        "number" => "number | number[] | Float64Array".into(),
                        "number[]" => "number | (number[] | Float64Array)[]".into(),
                        _ => format!("number | {}[]", self.ty_paren(&args[0])),
                    },
                    // a name the binding declares is named, not generated or inlined (the
                    // core's `Region` is declared in the contract's form)
                    _ if self.declared.contains(&name) => {
                        self.named.insert(name.clone());
                        name
                    }
                    _ => {
                        if let Some(Def {
                            item: Item::Type(alias),
                        }) = self.defs.get(&name)
                        {
                            let aliased = (*alias.ty).clone();
                            return self.ty(&aliased, None);
                        }
                        if self.defs.contains_key(&name) {
                            let name = self.ts_name(&name);
                            self.want(&name);
                            name
                        } else {
                            self.warnings
                                .push(format!("type {name} is not a serde type of the core"));
                            "unknown".into()
                        }
                    }
                }
            }
            other => {
                self.warnings.push(format!(
                    "unsupported type {}",
                    other.to_token_stream_string()
                ));
                "unknown".into()
            }
        }
    }

    /// The TypeScript name of the core type `name`: the name its form is renamed to where a
    /// type is registered under it, which is how it is written: a derived form's
    /// (`#[serde(rename = "BoxRegion")] struct AxisBoxRepr`), or the form of a type written
    /// through it (`LinearGaussianTransition` through `#[serde(rename = "TransitionRows")]
    /// struct TransitionRepr`, written as the core's `TransitionRows`); else its own.
    fn ts_name(&self, name: &str) -> String {
        match serde_of(item_attrs(&self.defs[name].item)).rename {
            Some(r) if r != name && self.defs.contains_key(&r) => r,
            _ => name.to_string(),
        }
    }

    /// The one field of a variant that JavaScript gives bare (`names_rule::BARE`: `{ polygon:
    /// [[x, y], …] }` for `Polygon(PolygonRepr { vertices })`), with its `with`.
    fn bare_field(&self, variant: &str, t: &Type) -> Option<(Type, Option<String>)> {
        let (_, field) = names_rule::BARE.iter().find(|(v, _)| *v == variant)?;
        let Type::Path(p) = t else { return None };
        let name = p.path.segments.last()?.ident.to_string();
        let Some(Def {
            item: Item::Struct(st),
        }) = self.defs.get(&name)
        else {
            return None;
        };
        let f = st
            .fields
            .iter()
            .find(|f| f.ident.as_ref().is_some_and(|i| i == field))?;
        Some((f.ty.clone(), serde_of(&f.attrs).with))
    }

    fn ty_paren(&mut self, t: &Type) -> String {
        let s = self.ty(t, None);
        if s.contains(" | ") || s.contains(" & ") {
            format!("({s})")
        } else {
            s
        }
    }

    fn doc_block(lines: &[String], indent: &str) -> String {
        if lines.is_empty() {
            return String::new();
        }
        let mut s = format!("{indent}/**\n");
        for l in lines {
            s += &format!("{indent} * {}\n", l.replace("*/", "*\\/")).replace(" * \n", " *\n");
        }
        s + &format!("{indent} */\n")
    }

    fn fields(&mut self, owner: &str, fields: &Fields, container: &Serde, indent: &str) -> String {
        let mut s = String::new();
        for f in fields.iter() {
            let fs = serde_of(&f.attrs);
            if fs.skip {
                continue;
            }
            let rust = f.ident.as_ref().unwrap().to_string();
            let js = fs
                .rename
                .clone()
                .unwrap_or_else(|| self.field_name(owner, &rust));
            self.holder = rust.clone();
            let (ty, opt) = match &f.ty {
                Type::Path(p) if p.path.segments.last().unwrap().ident == "Option" => {
                    let PathArguments::AngleBracketed(a) =
                        &p.path.segments.last().unwrap().arguments
                    else {
                        unreachable!()
                    };
                    let GenericArgument::Type(inner) = &a.args[0] else {
                        unreachable!()
                    };
                    match fs.with.as_deref() {
                        // `serde_shapes::nullable`: always written, null for `None`
                        Some(w) if w.ends_with("nullable") => (
                            format!("{} | null", self.ty(inner, None)),
                            fs.default || container.default,
                        ),
                        with => (self.ty(inner, with), true),
                    }
                }
                t => (
                    self.ty(t, fs.with.as_deref()),
                    fs.default || container.default || fs.optional_out,
                ),
            };
            s += &Self::doc_block(&docs(&f.attrs), indent);
            s += &format!("{indent}{js}{}: {ty};\n", if opt { "?" } else { "" });
        }
        s
    }

    pub fn emit(&mut self, name: &str) -> String {
        let def = &self.defs[name];
        let item = def.item.clone();
        match item {
            Item::Struct(st) => {
                let c = serde_of(&st.attrs);
                if let Some(repr) = &c.try_from {
                    let repr_ty: Type = syn::parse_str(repr).unwrap();
                    let inner = self.ty(&repr_ty, None);
                    return format!(
                        "{}export type {name} = {inner};\n",
                        Self::doc_block(&docs(&st.attrs), "")
                    );
                }
                match &st.fields {
                    Fields::Named(_) => {
                        let body = self.fields(name, &st.fields, &c, "    ");
                        format!(
                            "{}export interface {name} {{\n{body}}}\n",
                            Self::doc_block(&docs(&st.attrs), "")
                        )
                    }
                    Fields::Unnamed(u) => {
                        let parts: Vec<String> =
                            u.unnamed.iter().map(|f| self.ty(&f.ty, None)).collect();
                        let t = if parts.len() == 1 {
                            parts[0].clone()
                        } else {
                            format!("[{}]", parts.join(", "))
                        };
                        format!(
                            "{}export type {name} = {t};\n",
                            Self::doc_block(&docs(&st.attrs), "")
                        )
                    }
                    Fields::Unit => format!("export type {name} = null;\n"),
                }
            }
            Item::Enum(en) => {
                let c = serde_of(&en.attrs);
                let mut alts = Vec::new();
                for v in &en.variants {
                    let vs = serde_of(&v.attrs);
                    let rust_tag = vs.rename.clone().unwrap_or_else(|| {
                        rename_variant(&v.ident.to_string(), c.rename_all.as_deref())
                    });
                    // as `de.rs` reads it: camelCase, the renames of `names_rule::ANY_PARENT`
                    let tag = names_rule::js_name_of("", &rust_tag);
                    let doc = docs(&v.attrs);
                    let body = match &v.fields {
                        Fields::Unit => None,
                        Fields::Unnamed(u) if u.unnamed.len() == 1 => {
                            Some(match self.bare_field(&rust_tag, &u.unnamed[0].ty) {
                                Some((t, with)) => self.ty(&t, with.as_deref()),
                                None => {
                                    let field = serde_of(&u.unnamed[0].attrs).with;
                                    self.ty(&u.unnamed[0].ty, field.or(vs.with).as_deref())
                                }
                            })
                        }
                        Fields::Unnamed(u) => {
                            let parts: Vec<String> =
                                u.unnamed.iter().map(|f| self.ty(&f.ty, None)).collect();
                            Some(format!("[{}]", parts.join(", ")))
                        }
                        Fields::Named(_) => Some(format!(
                            "{{\n{}    }}",
                            self.fields(name, &v.fields, &Serde::default(), "        ")
                        )),
                    };
                    // an untagged variant (`#[serde(untagged)]`) is written as its body
                    let alt = match (body, c.untagged || vs.untagged, &c.tag) {
                        (None, _, None) => format!("\"{tag}\""),
                        (None, _, Some(t)) => format!("{{ {t}: \"{tag}\" }}"),
                        (Some(b), true, _) => b,
                        (Some(b), false, Some(t)) => format!("({{ {t}: \"{tag}\" }} & {b})"),
                        (Some(b), false, None) => format!("{{ {tag}: {b} }}"),
                    };
                    alts.push(format!("{}    | {alt}", Self::doc_block(&doc, "    ")));
                }
                format!(
                    "{}export type {name} =\n{};\n",
                    Self::doc_block(&docs(&en.attrs), ""),
                    alts.join("\n")
                )
            }
            Item::Type(t) => {
                let ty = self.ty(&t.ty, None);
                format!(
                    "{}export type {name} = {ty};\n",
                    Self::doc_block(&docs(&t.attrs), "")
                )
            }
            _ => unreachable!(),
        }
    }
}

/// The declarations of `roots` (names of serde types in `defs`) and of every type they hold,
/// with the warnings (types it could not render, written `unknown`). (Used by the tests; the
/// build script passes the binding's own names to [`declarations_with`].)
#[allow(dead_code)]
pub fn declarations(defs: &BTreeMap<String, Def>, roots: &[&String]) -> (String, Vec<String>) {
    declarations_with(defs, roots, &BTreeSet::new())
}

/// [`declarations`], with the names of core types the binding declares itself (`declared`:
/// named where held, never generated).
pub fn declarations_with(
    defs: &BTreeMap<String, Def>,
    roots: &[&String],
    declared: &BTreeSet<String>,
) -> (String, Vec<String>) {
    let (out, warnings, _) = declarations_reaching(defs, roots, declared);
    (out, warnings)
}

/// [`declarations_with`], and the names the declarations reach: the types generated and the
/// declared names they hold.
pub fn declarations_reaching(
    defs: &BTreeMap<String, Def>,
    roots: &[&String],
    declared: &BTreeSet<String>,
) -> (String, Vec<String>, BTreeSet<String>) {
    // twice: the first pass learns which fields hold each type (their names decide the
    // JavaScript names of the matrix fields), the second writes
    let mut parents = BTreeMap::new();
    let mut out = String::new();
    let mut warnings = Vec::new();
    let mut reached = BTreeSet::new();
    for _ in 0..2 {
        let mut g = Gen {
            defs,
            queue: VecDeque::new(),
            seen: BTreeSet::new(),
            warnings: vec![],
            holder: String::new(),
            parents: std::mem::take(&mut parents),
            declared,
            named: BTreeSet::new(),
        };
        for r in roots {
            g.want(r);
        }
        out.clear();
        while let Some(n) = g.queue.pop_front() {
            out += &g.emit(&n);
            out.push('\n');
        }
        parents = g.parents;
        warnings = g.warnings;
        reached = g.seen.into_iter().chain(g.named).collect();
    }
    (out, warnings, reached)
}

/// The declaration of an alias `(name, ty, doc)` of `ts_aliases.rs`: a doc that does not end
/// in a period is followed by ": the core's `ty`.".
pub fn alias(name: &str, ty: &str, doc: &str) -> String {
    let doc = match doc.ends_with('.') {
        true => doc.to_string(),
        false => format!("{doc}: the core's `{ty}`."),
    };
    let lines: Vec<String> = doc.lines().map(str::to_string).collect();
    format!("{}export type {name} = {ty};\n", Gen::doc_block(&lines, ""))
}

/// The declarations of a part: the core types its `roots` reach (as [`declarations_with`]) and
/// the aliases of `table` (`ts_aliases.rs`) it reaches. An alias goes in when its name is
/// among the roots or the names the part's own declarations hold (`mentioned`), or either of
/// its names is reached by the generated types; the type it names then becomes a root (the
/// filters' own `FilterEstimateLoss` holds `BernoulliCosts`, which brings in the core's
/// `Costs`).
pub fn part_declarations(
    defs: &BTreeMap<String, Def>,
    roots: &BTreeSet<String>,
    mentioned: &BTreeSet<String>,
    declared: &BTreeSet<String>,
    table: &[(&str, &str, &str)],
) -> (String, Vec<String>) {
    let mut roots = roots.clone();
    let mut chosen = vec![false; table.len()];
    loop {
        let wanted: Vec<&String> = roots
            .iter()
            .filter(|r| !declared.contains(*r) && defs.contains_key(*r))
            .collect();
        let (out, warnings, reached) = declarations_reaching(defs, &wanted, declared);
        let mut grew = false;
        for (i, (name, ty, _)) in table.iter().enumerate() {
            let named = mentioned.contains(*name) || roots.contains(*name);
            if !chosen[i] && (named || reached.contains(*name) || reached.contains(*ty)) {
                chosen[i] = true;
                grew = true;
                roots.insert(ty.to_string());
            }
        }
        if !grew {
            let aliases: String = table
                .iter()
                .zip(&chosen)
                .filter(|(_, c)| **c)
                .map(|((name, ty, doc), _)| alias(name, ty, doc) + "\n")
                .collect();
            return (aliases + &out, warnings);
        }
    }
}

/// Whether items with these attributes are compiled: their `#[cfg(…)]` (features, `any`,
/// `all`, `not`; `test` is off in a build) holds. Other predicates count as true.
pub fn cfg_enabled(attrs: &[syn::Attribute], feature: &dyn Fn(&str) -> bool) -> bool {
    attrs.iter().filter(|a| a.path().is_ident("cfg")).all(|a| {
        a.parse_args::<syn::Meta>()
            .is_ok_and(|m| cfg_holds(&m, feature))
    })
}

/// The value of one `cfg` predicate.
fn cfg_holds(m: &syn::Meta, feature: &dyn Fn(&str) -> bool) -> bool {
    match m {
        syn::Meta::Path(p) => !p.is_ident("test"),
        syn::Meta::NameValue(nv) if nv.path.is_ident("feature") => match &nv.value {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) => feature(&s.value()),
            _ => true,
        },
        syn::Meta::NameValue(_) => true,
        syn::Meta::List(l) => {
            let Ok(args) =
                l.parse_args_with(Punctuated::<syn::Meta, syn::Token![,]>::parse_terminated)
            else {
                return true;
            };
            let mut it = args.iter().map(|a| cfg_holds(a, feature));
            if l.path.is_ident("any") {
                it.any(|b| b)
            } else if l.path.is_ident("all") {
                it.all(|b| b)
            } else if l.path.is_ident("not") {
                !it.next().unwrap_or(true)
            } else {
                true
            }
        }
    }
}

/// The attributes of a top-level item (none for the kinds bindings do not use).
pub fn item_attrs(item: &Item) -> &[syn::Attribute] {
    match item {
        Item::Const(i) => &i.attrs,
        Item::Enum(i) => &i.attrs,
        Item::Fn(i) => &i.attrs,
        Item::Impl(i) => &i.attrs,
        Item::Macro(i) => &i.attrs,
        Item::Mod(i) => &i.attrs,
        Item::Static(i) => &i.attrs,
        Item::Struct(i) => &i.attrs,
        Item::Type(i) => &i.attrs,
        Item::Use(i) => &i.attrs,
        _ => &[],
    }
}
