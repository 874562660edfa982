//! `Serialize`/`Deserialize` of the validated types (feature `serde`): each is written as the
//! arguments of its constructor (Rust names) and read back THROUGH that constructor, so a
//! deserialised value is always valid and a bad one fails with the core's [`Error`] message
//! as the serde error.
//!
//! | type | shape | constructor |
//! |---|---|---|
//! | [`Gaussian`] | `{mean, cov}`, `cov` any [`Covariance`] form (written as rows; a bare number for n > 1 is `invalid_type` naming `cov`) | [`Gaussian::from_slices`] (`.mean`, `.cov`) |
//! | [`GaussianMixture`] | `[{weight, mean, cov}, …]`, at most [`MAX_GAUSSIANS`] | [`GaussianMixture::new`] (`[j].weight`, `[j].cov`) |
//! | [`LinearGaussianTransition`] | `{f, q}` | [`LinearGaussianTransition::new`] |
//! | [`LinearGaussianLikelihood`] | `{h, r}` | [`LinearGaussianLikelihood::new`] |
//! | [`Gospa`], [`Ospa`] | `{c, p, alpha}`, `{c, p}` | [`Gospa::new`], [`Ospa::new`] |
//! | [`Costs`] | written `{c00, c01, c10, c11, c}`; read as that, `"mpe"` or `{mmol: {asset, countermeasure}}` (errors name `.c01`, `.mmol.asset`) | [`Costs::new`], [`Costs::mpe`], [`Costs::mmol`] |
//! | [`ApplicationLoss`] | `{costs, radius}` | [`ApplicationLoss::new`] |
//! | [`AxisBox`], [`Ball`], [`Polygon`] | `{min, max}`, `{center, radius}`, `{vertices}` | their `new` |
//! | [`SplitLibrary`] | `{weights, means, sigma, lambda}` | [`SplitLibrary::new`] |
//! | [`MultiObjectLikelihood`] | `{detection, clutter_rate}` | [`MultiObjectLikelihood::new`] |
//! | [`ParticleSet`] | `{points, weights}` | [`ParticleSet::new`] |
//! | [`GmBernoulli`], [`Birth`] | `{existence, mixture}`, `{probability, mixture}` (a birth's errors name `.probability`, `.mixture[].weight`) | their `new` |
//! | [`Detection`] | `{probability, fov}` (`fov` optional; errors name `.probability`) | [`Detection::new`] |
//! | [`Density1`] | `{"gaussian": {mean, variance}}`, `{"uniform": {low, high}}`, `{"mixture": [{weight, mean, variance}, …]}`, `{"table": {x, density}}` (errors name `.gaussian.variance`, `.mixture[2].weight`, …); [`DensityOr`] with [`deserialize_density_or`] reads a value of those kinds or others of its own (a prior: a density or a Gaussian state) | [`Density1::gaussian`], … (a table's `cdf` is recomputed) |
//! | [`bounds::Detection`](BoundsDetection) | a number p (constant), `{"table": {x, probability}}` (errors name `.table.x[3]`, …) | [`BoundsDetection::constant`], [`BoundsDetection::table`] |
//! | [`LinearGaussian`] | `{detection, gain, offset, noise_variance}` | [`LinearGaussian::new`] |
//! | [`GaussianPrior`] | `{mean, cov}` (`cov` rows) | [`GaussianPrior::new`] |
//! | [`LinearGaussianSensor`] | `{detection_probability, gain, offset, noise_cov}` (`gain`, `noise_cov` rows) | [`LinearGaussianSensor::new`] |
//! | [`SpatialDensity`] | exactly one of `{mean, cov}`, `{mixture: [...]}`, `{particles, weights}` (`weights` optional; errors name `.mixture[2].cov`, `.particles[1]`) | [`SpatialDensity::gaussian`], [`SpatialDensity::mixture`], [`SpatialDensity::particles`] |
//! | [`Region`] | `{"box": {min, max}}`, `{"polygon": {vertices}}`, `{"ball": {center, radius}}`, `{"union": [regions]}`, `{"intersection": [regions]}`, `{"complement": region}` (errors name `.box.max[0]`, `.union[1]`, …) | [`AxisBox::new`], [`Polygon::new`], [`Ball::new`], [`Region::union`], … |
//!
//! Errors of the Gaussian types name the field relative to the value being read (`.cov`,
//! `[2].weight`), so that a deserializer that tracks paths (the JavaScript one) continues its
//! own path with them: `options.mixture` + `[2].cov`.
//!
//! No paper: these are data formats only.

use alloc::boxed::Box;
use alloc::vec::Vec;

use nalgebra::DMatrix;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::bernoulli::{ApplicationLoss, Costs, DensityKind, ParticleSet, SpatialDensity};
use crate::bounds::{Density1, Detection as BoundsDetection, JdeDetectionOptions, LinearGaussian};
use crate::error::Error;
use crate::filters::{
    Birth, Detection, GmBernoulli, LinearGaussianLikelihood, LinearGaussianTransition,
};
use crate::gaussian::{Gaussian, GaussianMixture};
use crate::metrics::{Gospa, Ospa};
use crate::regions::{AxisBox, Ball, Node, Polygon, Region};
use crate::serde_shapes::{Covariance, MAX_GAUSSIANS, covariance_row_major, matrix};
use crate::smc::MultiObjectLikelihood;
use crate::splitting::SplitLibrary;

/// Implements `Serialize` by writing `$repr` built from `&self`, and `Deserialize` by reading
/// `$repr` and passing it to the (fallible) constructor. With `below "field"`, the
/// constructor names its errors under `field` (`birth.probability`) and they are given
/// relative to the value read (`.probability`; see [`below`]).
macro_rules! through_constructor {
    ($ty:ty, $repr:ty, |$s:ident| $to:expr, |$r:ident| $from:expr $(, below $field:literal)?) => {
        impl Serialize for $ty {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let $s = self;
                let repr: $repr = $to;
                repr.serialize(serializer)
            }
        }

        impl<'de> Deserialize<'de> for $ty {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let $r = <$repr>::deserialize(deserializer)?;
                let built: Result<Self, Error> = $from;
                $(let built = built.map_err(|e| below(e, $field));)?
                built.map_err(D::Error::custom)
            }
        }
    };
}

/// A constructor's error about `field.x` (its own name for the value, `detection.probability`)
/// named relative to the value (`.probability`), so that a path-tracking deserializer
/// continues its own path with it (`config.detection` + `.probability`).
fn below(e: Error, field: &str) -> Error {
    e.map_field(|what| match what.strip_prefix(field) {
        Some(rest) if matches!(rest.as_bytes().first(), Some(b'.' | b'[')) => rest.into(),
        _ => what.into(),
    })
}

#[derive(Serialize)]
struct GaussianRepr {
    mean: Vec<f64>,
    #[serde(with = "matrix")]
    cov: DMatrix<f64>,
}

/// Reads a covariance for a mean of length n and checks it in place, so that a
/// path-tracking deserializer names the covariance itself: a bare number for n ≠ 1 is a type
/// error (`invalid_type`), a misfit of lengths a value error (`custom`, relative: `[1] has
/// length 1, expected 2`).
struct CovarianceSeed(usize);

impl<'de> serde::de::DeserializeSeed<'de> for CovarianceSeed {
    type Value = Vec<f64>;
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Vec<f64>, D::Error> {
        let cov = Covariance::deserialize(deserializer)?;
        covariance_fit(cov, self.0, "", |x, n| {
            D::Error::invalid_type(
                serde::de::Unexpected::Float(x),
                &alloc::format!("a nested {n}×{n} array (a bare number is a 1D variance)").as_str(),
            )
        })
    }
}

/// `cov`'s n·n row-major entries ([`covariance_row_major`] at `at`); `wrong_type` makes the
/// error for a bare number when n ≠ 1, any other misfit is a `custom` error (its message
/// relative: a leading path `at` or none).
fn covariance_fit<E: serde::de::Error>(
    cov: Covariance,
    n: usize,
    at: &str,
    wrong_type: impl FnOnce(f64, usize) -> E,
) -> Result<Vec<f64>, E> {
    let bare = match &cov {
        crate::serde_shapes::ScalarOr::Scalar(x) => Some(*x),
        _ => None,
    };
    covariance_row_major(cov, n, at).map_err(|e| match bare {
        Some(x) if e.wrong_type => wrong_type(x, n),
        _ => E::custom(e.message.trim_start()),
    })
}

/// A covariance as read: checked against the mean when the mean came first, else as given.
enum CovRead {
    Checked(Vec<f64>),
    Raw(Covariance),
}

/// The mean and the row-major covariance of a Gaussian read from a map, both required; a
/// covariance that came before the mean is checked against it here, its errors naming `.cov`.
fn mean_and_cov<E: serde::de::Error>(
    mean: Option<Vec<f64>>,
    cov: Option<CovRead>,
) -> Result<(Vec<f64>, Vec<f64>), E> {
    let mean = mean.ok_or_else(|| E::missing_field("mean"))?;
    let cov = match cov.ok_or_else(|| E::missing_field("cov"))? {
        CovRead::Checked(c) => c,
        CovRead::Raw(c) => covariance_fit(c, mean.len(), ".cov", |x, n| {
            E::invalid_type(
                serde::de::Unexpected::Float(x),
                &alloc::format!(
                    "an object whose cov is a nested {n}×{n} array (a bare number is a 1D \
                     variance)"
                )
                .as_str(),
            )
        })?,
    };
    Ok((mean, cov))
}

/// `{mean, cov}` (a [`Gaussian`]) or `{weight, mean, cov}` (a mixture component) as read,
/// the covariance row-major and fitting the mean.
struct GaussianRead {
    weight: f64,
    mean: Vec<f64>,
    cov: Vec<f64>,
}

const GAUSSIAN_FIELDS: &[&str] = &["mean", "cov"];
const COMPONENT_FIELDS: &[&str] = &["weight", "mean", "cov"];
const BERNOULLI_FIELDS: &[&str] = &["existence", "mean", "cov"];

/// Reads [`GaussianRead`] with the keys `fields`: `mean`, `cov` and, when there are three, the
/// weight first (`weight` of a mixture component, `existence` of a Bernoulli).
struct GaussianVisitor(&'static [&'static str]);

impl<'de> serde::de::Visitor<'de> for GaussianVisitor {
    type Value = GaussianRead;
    fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "an object {{ {} }}", self.0.join(", "))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<GaussianRead, A::Error> {
        let fields = self.0;
        let weight_key = (fields.len() == 3).then(|| fields[0]);
        let (mut weight, mut mean, mut cov) = (None, None::<Vec<f64>>, None);
        while let Some(key) = map.next_key::<alloc::string::String>()? {
            match key.as_str() {
                k if Some(k) == weight_key => {
                    if weight.is_some() {
                        return Err(A::Error::duplicate_field(fields[0]));
                    }
                    weight = Some(map.next_value::<f64>()?);
                }
                "mean" => {
                    if mean.is_some() {
                        return Err(A::Error::duplicate_field("mean"));
                    }
                    mean = Some(map.next_value()?);
                }
                "cov" => {
                    if cov.is_some() {
                        return Err(A::Error::duplicate_field("cov"));
                    }
                    cov = Some(match &mean {
                        Some(m) => CovRead::Checked(map.next_value_seed(CovarianceSeed(m.len()))?),
                        None => CovRead::Raw(map.next_value()?),
                    });
                }
                _ => return Err(A::Error::unknown_field(&key, fields)),
            }
        }
        let weight = match (weight_key, weight) {
            (Some(k), None) => return Err(A::Error::missing_field(k)),
            (_, w) => w.unwrap_or(1.0),
        };
        let (mean, cov) = mean_and_cov::<A::Error>(mean, cov)?;
        Ok(GaussianRead { weight, mean, cov })
    }
}

impl GaussianRead {
    /// N(mean, cov); errors name the fields relative to the Gaussian at `at` (`.cov`,
    /// `[2].mean[1]`), which a path-tracking deserializer appends to its path.
    fn gaussian(&self, at: &str) -> Result<Gaussian, alloc::string::String> {
        Gaussian::from_slices(&self.mean, &self.cov, at).map_err(|e| alloc::format!("{e}"))
    }
}

impl Serialize for Gaussian {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        GaussianRepr {
            mean: self.mean().as_slice().to_vec(),
            cov: self.cov().clone(),
        }
        .serialize(serializer)
    }
}

/// `{mean, cov}`, `cov` in any [`Covariance`] form.
impl<'de> Deserialize<'de> for Gaussian {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer
            .deserialize_struct(
                "Gaussian",
                GAUSSIAN_FIELDS,
                GaussianVisitor(GAUSSIAN_FIELDS),
            )?
            .gaussian("")
            .map_err(D::Error::custom)
    }
}

#[derive(Serialize)]
struct ComponentRepr {
    weight: f64,
    mean: Vec<f64>,
    #[serde(with = "matrix")]
    cov: DMatrix<f64>,
}

/// A mixture component as read.
struct ComponentIn(GaussianRead);

impl<'de> Deserialize<'de> for ComponentIn {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer
            .deserialize_struct(
                "WeightedGaussian",
                COMPONENT_FIELDS,
                GaussianVisitor(COMPONENT_FIELDS),
            )
            .map(ComponentIn)
    }
}

/// The mixture of the components read; errors relative to the array (`[2].cov`), or naming
/// the array itself (more than [`MAX_GAUSSIANS`]).
fn mixture_in(read: Vec<ComponentIn>, at: &str) -> Result<GaussianMixture, alloc::string::String> {
    if read.len() > MAX_GAUSSIANS {
        return Err(alloc::format!(
            "{at}has {} entries, at most {MAX_GAUSSIANS} are supported",
            read.len()
        ));
    }
    let mut components = Vec::with_capacity(read.len());
    for (j, ComponentIn(c)) in read.iter().enumerate() {
        components.push((c.weight, c.gaussian(&alloc::format!("{at}[{j}]"))?));
    }
    GaussianMixture::new(components, at).map_err(|e| alloc::format!("{e}"))
}

impl Serialize for GaussianMixture {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let components: Vec<ComponentRepr> = self
            .components()
            .iter()
            .map(|(w, g)| ComponentRepr {
                weight: *w,
                mean: g.mean().as_slice().to_vec(),
                cov: g.cov().clone(),
            })
            .collect();
        components.serialize(serializer)
    }
}

/// A Bernoulli component `{existence, mean, cov}` as read.
struct BernoulliIn(GaussianRead);

impl<'de> Deserialize<'de> for BernoulliIn {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer
            .deserialize_struct(
                "Bernoulli",
                BERNOULLI_FIELDS,
                GaussianVisitor(BERNOULLI_FIELDS),
            )
            .map(BernoulliIn)
    }
}

/// `[{existence, mean, cov}, …]` as `(existence, N(mean, cov))` pairs, at most
/// [`MAX_GAUSSIANS`] (module [`crate::serde_shapes::bernoullis`]); errors relative to the
/// array (`[2].cov`, `has 10001 entries, …`). The existences are not checked here.
pub(crate) fn read_bernoullis<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<Vec<(f64, Gaussian)>, D::Error> {
    let read = Vec::<BernoulliIn>::deserialize(deserializer)?;
    if read.len() > MAX_GAUSSIANS {
        return Err(D::Error::custom(alloc::format!(
            "has {} entries, at most {MAX_GAUSSIANS} are supported",
            read.len()
        )));
    }
    read.iter()
        .enumerate()
        .map(|(j, BernoulliIn(c))| {
            let g = c.gaussian(&alloc::format!("[{j}]"));
            g.map(|g| (c.weight, g)).map_err(D::Error::custom)
        })
        .collect()
}

/// `(existence, Gaussian)` pairs written as `[{existence, mean, cov}, …]`.
pub(crate) fn write_bernoullis<S: Serializer>(
    items: &[(f64, Gaussian)],
    serializer: S,
) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct BernoulliRepr {
        existence: f64,
        mean: Vec<f64>,
        #[serde(with = "matrix")]
        cov: DMatrix<f64>,
    }
    let items: Vec<BernoulliRepr> = items
        .iter()
        .map(|(r, g)| BernoulliRepr {
            existence: *r,
            mean: g.mean().as_slice().to_vec(),
            cov: g.cov().clone(),
        })
        .collect();
    items.serialize(serializer)
}

/// `[{weight, mean, cov}, …]`, at most [`MAX_GAUSSIANS`] components.
impl<'de> Deserialize<'de> for GaussianMixture {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        mixture_in(Vec::<ComponentIn>::deserialize(deserializer)?, "").map_err(D::Error::custom)
    }
}

/// A `LinearGaussianTransition` as written: F and Q as rows, the form of the core's
/// `TransitionRows` (`{ F, Q }` in the bindings' names).
#[derive(Serialize, Deserialize)]
#[serde(rename = "TransitionRows")]
struct TransitionRepr {
    #[serde(with = "matrix")]
    f: DMatrix<f64>,
    #[serde(with = "matrix")]
    q: DMatrix<f64>,
}

through_constructor!(
    LinearGaussianTransition,
    TransitionRepr,
    |t| TransitionRepr {
        f: t.f().clone(),
        q: t.q().clone(),
    },
    |r| LinearGaussianTransition::new(r.f, r.q)
);

#[derive(Serialize, Deserialize)]
struct LikelihoodRepr {
    #[serde(with = "matrix")]
    h: DMatrix<f64>,
    #[serde(with = "matrix")]
    r: DMatrix<f64>,
}

through_constructor!(
    LinearGaussianLikelihood,
    LikelihoodRepr,
    |l| LikelihoodRepr {
        h: l.h().clone(),
        r: l.r().clone(),
    },
    |r| LinearGaussianLikelihood::new(r.h, r.r)
);

#[derive(Serialize, Deserialize)]
struct GospaRepr {
    c: f64,
    p: f64,
    alpha: f64,
}

through_constructor!(
    Gospa,
    GospaRepr,
    |g| GospaRepr {
        c: g.cutoff(),
        p: g.order(),
        alpha: g.alpha(),
    },
    |r| Gospa::new(r.c, r.p, r.alpha)
);

#[derive(Serialize, Deserialize)]
struct OspaRepr {
    c: f64,
    p: f64,
}

through_constructor!(
    Ospa,
    OspaRepr,
    |o| OspaRepr {
        c: o.cutoff(),
        p: o.order(),
    },
    |r| Ospa::new(r.c, r.p)
);

#[derive(Serialize)]
struct CostsRepr {
    c00: f64,
    c01: f64,
    c10: f64,
    c11: f64,
    c: f64,
}

impl Serialize for Costs {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        CostsRepr {
            c00: self.c00(),
            c01: self.c01(),
            c10: self.c10(),
            c11: self.c11(),
            c: self.c(),
        }
        .serialize(serializer)
    }
}

/// The forms [`Costs`] are read in, as the error messages name them.
const COST_FORMS: &str = "'mpe', { mmol: { asset, countermeasure } } or { c00, c01, c10, c11, c }";
const COST_KEYS: [&str; 5] = ["c00", "c01", "c10", "c11", "c"];
const COST_FIELDS: &[&str] = &["mmol", "c00", "c01", "c10", "c11", "c"];

/// The MMOL preset's two costs as read: `{asset, countermeasure}`.
#[derive(Deserialize)]
struct MmolIn {
    asset: f64,
    countermeasure: f64,
}

/// A [`Costs`] constructor's error as a serde error naming the field relative to the costs
/// (`.c01`, `.mmol.asset`), which a path-tracking deserializer appends to its path.
fn costs_error<E: serde::de::Error>(e: Error) -> E {
    E::custom(e.map_field(|f| f.strip_prefix("costs").unwrap_or(f).into()))
}

// [`Costs`] as read: the visitor below reads one of these forms (its messages name them,
// `COST_FORMS`) and builds the costs from it (written back as the five costs, `CostsRepr`);
// the JavaScript binding's TypeScript generator declares `Costs` by this form (its `rename`).
/// Costs of the loss (7) of Narykov, Üney & Ralph, "Optimal Bernoulli point estimation with
/// applications" (paper 000): the MPE preset `'mpe'` (0, 1, 1, 0, 1), the MMOL preset
/// `{ mmol: { asset: c_A, countermeasure: c_M } }` (c00 = 0, c01 = c_A, c10 = c_M, c11 = c_M,
/// c = c_A), or the five costs (finite, ≥ 0).
#[derive(Serialize)]
#[serde(rename = "Costs", rename_all = "lowercase")]
enum CostsForm {
    /// `'mpe'`: the minimum-probability-of-error preset (0, 1, 1, 0, 1) of Table I.
    Mpe,
    /// `{ mmol: { asset, countermeasure } }`: the MMOL preset of Table I.
    Mmol {
        /// The value c_A of the asset a missed target costs (finite, ≥ 0).
        asset: f64,
        /// The cost c_M of the countermeasure, spent on each report (finite, ≥ 0).
        countermeasure: f64,
    },
    /// `{ c00, c01, c10, c11, c }`: the five costs, each finite and ≥ 0.
    #[serde(untagged)]
    Five {
        /// No target, none reported.
        c00: f64,
        /// A missed target.
        c01: f64,
        /// A report without a target (a false alarm).
        c10: f64,
        /// A report of a present target.
        c11: f64,
        /// Added to c11 when the report is farther than the radius r0 from the target.
        c: f64,
    },
}

impl CostsForm {
    /// The costs, through [`Costs`]' constructors (errors named relative to the costs).
    #[inline(always)]
    fn costs<E: serde::de::Error>(self) -> Result<Costs, E> {
        match self {
            CostsForm::Mpe => Ok(Costs::mpe()),
            CostsForm::Mmol {
                asset,
                countermeasure,
            } => Costs::mmol(asset, countermeasure).map_err(costs_error),
            CostsForm::Five {
                c00,
                c01,
                c10,
                c11,
                c,
            } => Costs::new(c00, c01, c10, c11, c).map_err(costs_error),
        }
    }
}

/// Reads the three forms of the loss (7)'s costs: the string `"mpe"` ([`Costs::mpe`]),
/// `{mmol: {asset, countermeasure}}` ([`Costs::mmol`]) or the five costs `{c00, c01, c10, c11,
/// c}` ([`Costs::new`]); written back as the five costs.
impl<'de> Deserialize<'de> for Costs {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::{MapAccess, Unexpected, Visitor};
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Costs;
            fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str(COST_FORMS)
            }
            fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<Costs, E> {
                match s {
                    "mpe" => CostsForm::Mpe.costs(),
                    other => Err(E::custom(alloc::format!(
                        "must be {COST_FORMS}, got {}",
                        crate::error::Quoted(other)
                    ))),
                }
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Costs, A::Error> {
                let mut values = [None; 5];
                let mut mmol = None;
                while let Some(key) = map.next_key::<alloc::string::String>()? {
                    if key == "mmol" {
                        mmol = Some(map.next_value::<MmolIn>()?);
                    } else if let Some(i) = COST_KEYS.iter().position(|k| *k == key) {
                        values[i] = Some(map.next_value::<f64>()?);
                    } else {
                        return Err(A::Error::unknown_field(&key, COST_FIELDS));
                    }
                }
                if let Some(m) = mmol {
                    if values.iter().any(Option::is_some) {
                        return Err(A::Error::invalid_type(
                            Unexpected::Other("mmol together with c00…c"),
                            &COST_FORMS,
                        ));
                    }
                    return CostsForm::Mmol {
                        asset: m.asset,
                        countermeasure: m.countermeasure,
                    }
                    .costs();
                }
                let mut c = [0.0; 5];
                for (i, v) in values.iter().enumerate() {
                    c[i] = v.ok_or_else(|| A::Error::missing_field(COST_KEYS[i]))?;
                }
                CostsForm::Five {
                    c00: c[0],
                    c01: c[1],
                    c10: c[2],
                    c11: c[3],
                    c: c[4],
                }
                .costs()
            }
        }
        deserializer.deserialize_any(V)
    }
}

#[derive(Serialize, Deserialize)]
struct ApplicationLossRepr {
    costs: Costs,
    radius: f64,
}

through_constructor!(
    ApplicationLoss,
    ApplicationLossRepr,
    |l| ApplicationLossRepr {
        costs: *l.costs(),
        radius: l.radius(),
    },
    |r| ApplicationLoss::new(r.costs, r.radius)
);

/// An axis-aligned box `{ min, max }` (closed; any dimension).
#[derive(Serialize, Deserialize)]
#[serde(rename = "BoxRegion")]
struct AxisBoxRepr {
    /// The lower corner: the smallest coordinate along each axis.
    #[serde(with = "crate::serde_shapes::numbers")]
    min: Vec<f64>,
    /// The upper corner: the largest coordinate along each axis (each entry ≥ the lower one).
    #[serde(with = "crate::serde_shapes::numbers")]
    max: Vec<f64>,
}

through_constructor!(
    AxisBox,
    AxisBoxRepr,
    |b| AxisBoxRepr {
        min: b.min().to_vec(),
        max: b.max().to_vec(),
    },
    |r| AxisBox::new(&r.min, &r.max, "box")
);

/// A disc `{ center, radius }` (a closed ball in more than two dimensions; JavaScript's
/// `disc` is the core's `ball`).
#[derive(Serialize, Deserialize)]
#[serde(rename = "DiscRegion")]
struct BallRepr {
    /// The disc's centre, one number per position coordinate.
    #[serde(with = "crate::serde_shapes::numbers")]
    center: Vec<f64>,
    /// The disc's radius, > 0.
    radius: f64,
}

through_constructor!(
    Ball,
    BallRepr,
    |b| BallRepr {
        center: b.center().to_vec(),
        radius: b.radius(),
    },
    |r| Ball::new(&r.center, r.radius, "ball")
);

#[derive(Serialize, Deserialize)]
struct PolygonRepr {
    vertices: Vec<[f64; 2]>,
}

through_constructor!(
    Polygon,
    PolygonRepr,
    |p| PolygonRepr {
        vertices: p.vertices().to_vec(),
    },
    |r| Polygon::new(&r.vertices, "polygon")
);

#[derive(Serialize, Deserialize)]
struct SplitLibraryRepr {
    weights: Vec<f64>,
    means: Vec<f64>,
    sigma: f64,
    lambda: f64,
}

through_constructor!(
    SplitLibrary,
    SplitLibraryRepr,
    |l| SplitLibraryRepr {
        weights: l.weights().to_vec(),
        means: l.means().to_vec(),
        sigma: l.sigma(),
        lambda: l.lambda(),
    },
    |r| SplitLibrary::new(&r.weights, &r.means, r.sigma, r.lambda)
);

#[derive(Serialize, Deserialize)]
struct MultiObjectLikelihoodRepr {
    detection: f64,
    clutter_rate: f64,
}

through_constructor!(
    MultiObjectLikelihood,
    MultiObjectLikelihoodRepr,
    |m| MultiObjectLikelihoodRepr {
        detection: m.detection(),
        clutter_rate: m.clutter_rate(),
    },
    |r| MultiObjectLikelihood::new(r.detection, r.clutter_rate)
);

#[derive(Serialize, Deserialize)]
struct ParticleSetRepr {
    points: Vec<Vec<f64>>,
    weights: Vec<f64>,
}

through_constructor!(
    ParticleSet,
    ParticleSetRepr,
    |p| ParticleSetRepr {
        points: (0..p.len()).map(|i| p.point(i).to_vec()).collect(),
        weights: p.weights().to_vec(),
    },
    |r| ParticleSet::new(&r.points, Some(&r.weights))
);

/// A Bernoulli with a Gaussian-mixture (GM) spatial density, eq. (39) of paper 001: f(∅) =
/// 1 − r, f({x}) = r p(x).
#[derive(Serialize, Deserialize)]
struct GmBernoulliRepr {
    /// The existence probability r ∈ [0, 1].
    existence: f64,
    /// The spatial density p(x), a Gaussian mixture (weights sum to 1).
    #[serde(with = "crate::serde_shapes::components")]
    mixture: GaussianMixture,
}

through_constructor!(
    GmBernoulli,
    GmBernoulliRepr,
    |b| GmBernoulliRepr {
        existence: b.existence,
        mixture: b.mixture.clone(),
    },
    |r| GmBernoulli::new(r.existence, r.mixture)
);

/// Object birth: p_b and the birth density b(x) (eq. (43) of paper 001; weights sum to 1; may
/// be empty when p_b = 0).
#[derive(Serialize, Deserialize)]
#[serde(rename = "Birth")]
struct BirthRepr {
    /// The birth probability p_b ∈ [0, 1]: the probability that an object appears in one step
    /// when none exists.
    probability: f64,
    /// The birth density b(x) of a new object's state, a Gaussian mixture (weights sum to 1).
    #[serde(default)]
    mixture: GaussianMixture,
}

through_constructor!(
    Birth,
    BirthRepr,
    |b| BirthRepr {
        probability: b.probability,
        mixture: b.mixture.clone(),
    },
    |r| Birth::new(r.probability, r.mixture),
    below "birth"
);

/// Object detection: p_D(x; S) = 1_S(x) p_D, eq. (51) of LeGrand & Ferrari, "Split Happens!
/// Imprecise and negative information in Gaussian mixture random finite set filtering" (paper
/// 001).
#[derive(Serialize, Deserialize)]
#[serde(rename = "Detection")]
struct DetectionRepr {
    /// The detection probability p_D ∈ [0, 1] inside the field of view S.
    probability: f64,
    /// The field of view S; omitted: detection everywhere.
    #[serde(default)]
    fov: Option<Region>,
}

through_constructor!(
    Detection,
    DetectionRepr,
    |d| DetectionRepr {
        probability: d.probability,
        fov: d.fov.clone(),
    },
    |r| Detection::new(r.probability, r.fov),
    below "detection"
);

/// A region written as the constructor that builds it (externally tagged, snake_case).
#[derive(Serialize)]
#[serde(rename = "Region", rename_all = "snake_case")]
enum RegionRef<'a> {
    Box(&'a AxisBox),
    Polygon(&'a Polygon),
    Ball(&'a Ball),
    Union(&'a [Region]),
    Intersection(&'a [Region]),
    Complement(&'a Region),
}

// [`RegionRef`] as read: the arguments of the constructors, which [`Region`]'s
// `Deserialize` calls itself (so that their errors name the part of the region at fault); the
// JavaScript binding's TypeScript generator declares `Region` by this form (its `rename`).
/// A region of the position subspace (the first state components): a closed box (any
/// dimension), a closed polygon (2D; either orientation; even–odd rule when
/// self-intersecting), or a closed disc (a ball in higher dimensions), or a union,
/// intersection or complement of regions. Exactly one key.
#[derive(Deserialize)]
#[serde(rename = "Region")]
enum RegionRepr {
    /// `{ box: { min, max } }`: an axis-aligned box.
    #[serde(rename = "box")]
    Box(AxisBoxRepr),
    /// `{ polygon: [[x, y], …] }`: a 2D polygon of at least three vertices, at most 1,000.
    #[serde(rename = "polygon")]
    Polygon(PolygonRepr),
    /// `{ disc: { center, radius } }`: a disc (a ball in more than two dimensions).
    #[serde(rename = "ball")]
    Ball(BallRepr),
    /// `{ union: [region, …] }`: inside any member (1 to 1,000, all of one dimension).
    #[serde(rename = "union")]
    Union(Vec<Region>),
    /// `{ intersection: [region, …] }`: inside every member (1 to 1,000, all of one
    /// dimension).
    #[serde(rename = "intersection")]
    Intersection(Vec<Region>),
    /// `{ complement: region }`: outside the region (open).
    #[serde(rename = "complement")]
    Complement(Box<Region>),
}

impl Serialize for Region {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self.node() {
            Node::Box(b) => RegionRef::Box(b),
            Node::Polygon(p) => RegionRef::Polygon(p),
            Node::Ball(b) => RegionRef::Ball(b),
            Node::Union(m) => RegionRef::Union(m),
            Node::Intersection(m) => RegionRef::Intersection(m),
            Node::Complement(r) => RegionRef::Complement(r),
        }
        .serialize(serializer)
    }
}

/// Read through the constructors ([`AxisBox::new`], [`Polygon::new`], [`Ball::new`],
/// [`Region::union`], [`Region::intersection`], [`Region::complement`]); an error names the
/// part at fault relative to the region (`.box.max[0]`, `.polygon[2][1]`, `.union[1]`,
/// `.union has 1001 members, …`), so a path-tracking deserializer continues its own path with
/// it (`options.fov` + `.box.max[0]`; the JavaScript one renders it in its names,
/// `.disc.radius` for `.ball.radius`).
impl<'de> Deserialize<'de> for Region {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let built = match RegionRepr::deserialize(deserializer)? {
            RegionRepr::Box(b) => AxisBox::new(&b.min, &b.max, "box").map(Region::from),
            RegionRepr::Polygon(p) => Polygon::new(&p.vertices, "polygon").map(Region::from),
            RegionRepr::Ball(b) => Ball::new(&b.center, b.radius, "ball").map(Region::from),
            RegionRepr::Union(m) => Region::union(m, "union"),
            RegionRepr::Intersection(m) => Region::intersection(m, "intersection"),
            RegionRepr::Complement(r) => Ok(Region::complement(*r)),
        };
        built.map_err(|e| D::Error::custom(e.map_field(|what| alloc::format!(".{what}"))))
    }
}

/// One component of a Gaussian mixture on the line: `{weight, mean, variance}`.
#[derive(Serialize, Deserialize)]
struct Density1Component {
    /// The component's weight, > 0 (the weights are normalised).
    weight: f64,
    /// The component's mean, finite.
    mean: f64,
    /// The component's variance, > 0.
    variance: f64,
}

// [`Density1`] as the arguments of its constructors; the JavaScript binding's TypeScript
// generator declares `Density1` by this form (its `rename`).
/// A density on the line, keyed by its kind: a Gaussian, a uniform density, a Gaussian
/// mixture (1 to 1,000 components) or a table (linear interpolation between knots, 0
/// outside, normalised).
#[derive(Serialize, Deserialize)]
#[serde(rename = "Density1", rename_all = "camelCase")]
enum Density1Repr {
    /// `{ gaussian: { mean, variance } }`: N(mean, variance).
    Gaussian {
        /// The mean, a finite number.
        mean: f64,
        /// The variance (> 0, a normal float: at least 2.2250738585072014e-308).
        variance: f64,
    },
    /// `{ uniform: { low, high } }`: U[low, high].
    Uniform {
        /// The lower end of the support, finite.
        low: f64,
        /// The upper end of the support, finite and > low.
        high: f64,
    },
    /// `{ mixture: [{ weight, mean, variance }, …] }`: a Gaussian mixture.
    Mixture(Vec<Density1Component>),
    /// `{ table: { x, density } }`: a tabulated density.
    Table {
        /// The knots x, strictly increasing (2 to 10,000).
        #[serde(with = "crate::serde_shapes::numbers")]
        x: Vec<f64>,
        /// Density ≥ 0 at each knot (any positive scale: it is normalised).
        #[serde(with = "crate::serde_shapes::numbers")]
        density: Vec<f64>,
    },
}

impl Serialize for Density1 {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Density1::Gaussian { mean, variance } => Density1Repr::Gaussian {
                mean: *mean,
                variance: *variance,
            },
            Density1::Uniform { low, high } => Density1Repr::Uniform {
                low: *low,
                high: *high,
            },
            Density1::Mixture(c) => Density1Repr::Mixture(
                c.iter()
                    .map(|&(weight, mean, variance)| Density1Component {
                        weight,
                        mean,
                        variance,
                    })
                    .collect(),
            ),
            Density1::Table { x, density, .. } => Density1Repr::Table {
                x: x.clone(),
                density: density.clone(),
            },
        }
        .serialize(serializer)
    }
}

/// A constructor's error about a part of the value being read, named relative to it
/// (`.gaussian.variance`, `.mixture[2].weight`, `.table.x[3]`): a path-tracking deserializer
/// (the JavaScript one) continues its own path with it.
fn relative(e: Error, kind: &str) -> alloc::string::String {
    alloc::format!("{}", e.within(&alloc::format!(".{kind}")))
}

/// [`Density1`] from its form through its constructors; their errors name the part at fault
/// relative to the value (`.gaussian.variance`).
fn density_from(repr: Density1Repr) -> Result<Density1, alloc::string::String> {
    match repr {
        Density1Repr::Gaussian { mean, variance } => {
            Density1::gaussian(mean, variance).map_err(|e| relative(e, "gaussian"))
        }
        Density1Repr::Uniform { low, high } => {
            Density1::uniform(low, high).map_err(|e| relative(e, "uniform"))
        }
        Density1Repr::Mixture(c) => {
            let c: Vec<(f64, f64, f64)> =
                c.iter().map(|c| (c.weight, c.mean, c.variance)).collect();
            Density1::mixture(&c).map_err(|e| relative(e, "mixture"))
        }
        Density1Repr::Table { x, density } => {
            Density1::table(&x, &density).map_err(|e| relative(e, "table"))
        }
    }
}

impl<'de> Deserialize<'de> for Density1 {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserialize_density_or(deserializer)
    }
}

impl DensityOr for Density1 {
    const KINDS: &'static [&'static str] = &DENSITY1_KINDS;
    fn density(d: Density1) -> Self {
        d
    }
}

/// The kinds of a [`Density1`], its keys as read and written.
pub const DENSITY1_KINDS: [&str; 4] = ["gaussian", "uniform", "mixture", "table"];

/// A value read as one of several kinds, `{kind: value}` (or a kind's bare name), some of
/// which are the [`Density1`] kinds: a prior that is a density on the line or a Gaussian
/// vector state, say. The density kinds are read as [`Density1`] (through its constructors,
/// errors relative to the value as there), the others by [`DensityOr::other`]. Read with
/// [`deserialize_density_or`].
pub trait DensityOr: Sized {
    /// Every kind, [`DENSITY1_KINDS`] among them, in the order an unknown kind's error lists
    /// them.
    const KINDS: &'static [&'static str];
    /// The value of a density kind.
    fn density(d: Density1) -> Self;
    /// The value of any other kind (default: an unknown kind).
    ///
    /// # Errors
    /// The variant's, or an unknown-variant error.
    fn other<'de, V: serde::de::VariantAccess<'de>>(kind: &str, v: V) -> Result<Self, V::Error> {
        let _ = v;
        Err(serde::de::Error::unknown_variant(kind, Self::KINDS))
    }
}

/// Reads a [`DensityOr`] (and [`Density1`] itself): the kinds are `T::KINDS`; a density
/// constructor's error is raised while the kind's value is being read, so a path-tracking
/// deserializer names it under the value (`options.clutter.density.gaussian.variance`).
///
/// # Errors
/// The deserializer's, or a density constructor's message.
pub fn deserialize_density_or<'de, T: DensityOr, D: Deserializer<'de>>(
    d: D,
) -> Result<T, D::Error> {
    struct Kinds<T>(core::marker::PhantomData<T>);
    impl<'de, T: DensityOr> serde::de::Visitor<'de> for Kinds<T> {
        type Value = T;
        fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            f.write_str("one of the kinds")
        }
        fn visit_enum<A: serde::de::EnumAccess<'de>>(self, a: A) -> Result<T, A::Error> {
            let (kind, variant): (alloc::string::String, _) = a.variant()?;
            if DENSITY1_KINDS.contains(&kind.as_str()) {
                let repr = Density1Repr::deserialize(OneKind { kind, variant })?;
                density_from(repr)
                    .map(T::density)
                    .map_err(serde::de::Error::custom)
            } else {
                T::other(&kind, variant)
            }
        }
    }
    d.deserialize_enum("Density1", T::KINDS, Kinds(core::marker::PhantomData))
}

/// A kind already read and its value, handed on as an enum of that one variant.
struct OneKind<A> {
    kind: alloc::string::String,
    variant: A,
}

impl<'de, A: serde::de::VariantAccess<'de>> Deserializer<'de> for OneKind<A> {
    type Error = A::Error;
    fn deserialize_any<W: serde::de::Visitor<'de>>(self, w: W) -> Result<W::Value, A::Error> {
        w.visit_enum(self)
    }
    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        option unit unit_struct newtype_struct seq tuple tuple_struct map struct enum
        identifier ignored_any
    }
}

impl<'de, A: serde::de::VariantAccess<'de>> serde::de::EnumAccess<'de> for OneKind<A> {
    type Error = A::Error;
    type Variant = AsNewtype<A>;
    fn variant_seed<S: serde::de::DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> Result<(S::Value, AsNewtype<A>), A::Error> {
        use serde::de::IntoDeserializer;
        let kind = seed.deserialize(self.kind.as_str().into_deserializer())?;
        Ok((kind, AsNewtype(self.variant)))
    }
}

/// A kind's value read as one value (`{"gaussian": …}`), whatever its Rust form, so that every
/// kind of a [`DensityOr`] reads (and fails) alike.
struct AsNewtype<A>(A);

impl<'de, A: serde::de::VariantAccess<'de>> serde::de::VariantAccess<'de> for AsNewtype<A> {
    type Error = A::Error;
    fn unit_variant(self) -> Result<(), A::Error> {
        self.0.unit_variant()
    }
    fn newtype_variant_seed<T: serde::de::DeserializeSeed<'de>>(
        self,
        seed: T,
    ) -> Result<T::Value, A::Error> {
        self.0.newtype_variant_seed(seed)
    }
    fn tuple_variant<V: serde::de::Visitor<'de>>(
        self,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, A::Error> {
        self.0.tuple_variant(len, visitor)
    }
    fn struct_variant<V: serde::de::Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, A::Error> {
        self.0.newtype_variant_seed(StructSeed(fields, visitor))
    }
}

/// Reads a struct with `fields` by `visitor`.
struct StructSeed<V>(&'static [&'static str], V);

impl<'de, V: serde::de::Visitor<'de>> serde::de::DeserializeSeed<'de> for StructSeed<V> {
    type Value = V::Value;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<V::Value, D::Error> {
        d.deserialize_struct("", self.0, self.1)
    }
}

/// [`BoundsDetection`] is written and read as its unchecked form
/// [`JdeDetectionOptions`](crate::bounds::JdeDetectionOptions): a number (a constant P_o, checked by
/// [`BoundsDetection::constant`]; its error names the value itself) or
/// `{"table": {x, probability}}` (checked by [`BoundsDetection::table`]; errors name
/// `.table.x[i]`, `.table.probability[i]`).
impl Serialize for BoundsDetection {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let raw = match self {
            BoundsDetection::Constant(p) => JdeDetectionOptions::Constant(*p),
            BoundsDetection::Table { x, probability } => JdeDetectionOptions::Table {
                x: x.clone(),
                probability: probability.clone(),
            },
        };
        raw.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for BoundsDetection {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        match JdeDetectionOptions::deserialize(deserializer)? {
            JdeDetectionOptions::Constant(p) => BoundsDetection::constant(p).map_err(|e| {
                let message = alloc::format!("{}", e.map_field(|_| "".into()));
                D::Error::custom(message.trim_start())
            }),
            JdeDetectionOptions::Table { x, probability } => {
                BoundsDetection::table(&x, &probability)
                    .map_err(|e| D::Error::custom(relative(e, "table")))
            }
        }
    }
}

#[derive(Serialize, Deserialize)]
struct LinearGaussianRepr {
    detection: BoundsDetection,
    gain: f64,
    offset: f64,
    noise_variance: f64,
}

through_constructor!(
    LinearGaussian,
    LinearGaussianRepr,
    |l| LinearGaussianRepr {
        detection: l.detection.clone(),
        gain: l.gain,
        offset: l.offset,
        noise_variance: l.noise_variance,
    },
    |r| LinearGaussian::new(r.detection, r.gain, r.offset, r.noise_variance)
);

/// Numbers `[x, …]`, written under this name, which the JavaScript binding declares (a list
/// of numbers or a `Float64Array`).
type Numbers = Vec<f64>;

// [`SpatialDensity`] as written (the weights always); read by [`DensityVisitor`]. The
// JavaScript binding's TypeScript generator declares `SpatialDensity` by this form (its
// `rename`; `weights` may be left out).
/// The spatial density of a Bernoulli: one Gaussian (any dimension, full covariance), a
/// Gaussian mixture (weights ≥ 0 with a positive sum; normalised), or weighted particles
/// (weights ≥ 0 with a positive sum, default equal; normalised). Exactly one form.
#[derive(Serialize)]
#[serde(rename = "SpatialDensity", untagged)]
enum SpatialDensityRepr {
    /// `{ mean, cov }`: one Gaussian.
    Gaussian(Gaussian),
    /// `{ mixture }`: a Gaussian mixture.
    Mixture {
        /// The mixture's components.
        mixture: GaussianMixture,
    },
    /// `{ particles, weights? }`: weighted particles.
    Particles {
        /// The particles, one point each.
        #[serde(with = "crate::serde_shapes::rows_of_numbers")]
        particles: Vec<Vec<f64>>,
        /// The particles' weights (default equal).
        #[serde(default)]
        weights: Numbers,
    },
}

impl Serialize for SpatialDensity {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::Error as _;
        let repr = match (self.kind(), self.as_gaussian(), self.as_particles()) {
            (DensityKind::Gaussian, Some(g), _) => SpatialDensityRepr::Gaussian(g.clone()),
            (DensityKind::Particles, _, Some(p)) => SpatialDensityRepr::Particles {
                particles: (0..p.len()).map(|i| p.point(i).to_vec()).collect(),
                weights: p.weights().to_vec(),
            },
            _ => {
                let components = self.mixture_components().unwrap_or_default();
                let owned = components
                    .into_iter()
                    .map(|(w, g)| (w, g.clone()))
                    .collect();
                let mixture = GaussianMixture::new(owned, "density.mixture")
                    .map_err(|e| S::Error::custom(alloc::format!("{e}")))?;
                SpatialDensityRepr::Mixture { mixture }
            }
        };
        repr.serialize(serializer)
    }
}

/// The keys of a [`SpatialDensity`], and its forms as its error messages name them.
const DENSITY_FIELDS: &[&str] = &["mean", "cov", "mixture", "particles", "weights"];
const DENSITY_FORMS: &str =
    "exactly one of { mean, cov }, { mixture: [...] } or { particles: [...], weights }";

/// A constructor's error about the density being read, named relative to it
/// (`density.mixture[2].weight` → `.mixture[2].weight`, `sum of density.weights` →
/// `.weights sum`).
fn density_error(e: Error) -> alloc::string::String {
    let e = e.map_paths(|p| match p.strip_prefix("sum of density") {
        Some(rest) => alloc::format!("{rest} sum"),
        None => p.strip_prefix("density").unwrap_or(p).into(),
    });
    alloc::format!("{e}")
}

struct DensityVisitor;

impl<'de> serde::de::Visitor<'de> for DensityVisitor {
    type Value = SpatialDensity;
    fn expecting(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(DENSITY_FORMS)
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(
        self,
        mut map: A,
    ) -> Result<SpatialDensity, A::Error> {
        let mut mean: Option<Vec<f64>> = None;
        let mut cov: Option<CovRead> = None;
        let mut mixture: Option<GaussianMixture> = None;
        let mut particles: Option<Vec<Vec<f64>>> = None;
        let mut weights: Option<Vec<f64>> = None;
        while let Some(key) = map.next_key::<alloc::string::String>()? {
            let seen = match key.as_str() {
                "mean" => mean.replace(map.next_value()?).is_some(),
                "cov" => {
                    let read = match &mean {
                        Some(m) => CovRead::Checked(map.next_value_seed(CovarianceSeed(m.len()))?),
                        None => CovRead::Raw(map.next_value()?),
                    };
                    cov.replace(read).is_some()
                }
                "mixture" => mixture.replace(map.next_value()?).is_some(),
                "particles" => particles.replace(map.next_value()?).is_some(),
                "weights" => weights.replace(map.next_value()?).is_some(),
                _ => return Err(A::Error::unknown_field(&key, DENSITY_FIELDS)),
            };
            if seen {
                let field = DENSITY_FIELDS.iter().find(|f| **f == key);
                return Err(A::Error::duplicate_field(field.copied().unwrap_or("?")));
            }
        }
        let gaussian = mean.is_some() || cov.is_some();
        let forms = usize::from(gaussian)
            + usize::from(mixture.is_some())
            + usize::from(particles.is_some());
        if forms != 1 || (weights.is_some() && particles.is_none()) {
            let given = match forms {
                0 if weights.is_some() => "weights without particles",
                0 => "none of them",
                1 => "weights without particles",
                _ => "more than one",
            };
            return Err(A::Error::invalid_type(
                serde::de::Unexpected::Other(given),
                &DENSITY_FORMS,
            ));
        }
        let built = if let Some(m) = mixture {
            SpatialDensity::mixture(&m).map_err(density_error)
        } else if let Some(points) = particles {
            ParticleSet::new(&points, weights.as_deref())
                .map(SpatialDensity::particles)
                .map_err(density_error)
        } else {
            let (mean, cov) = mean_and_cov::<A::Error>(mean, cov)?;
            let read = GaussianRead {
                weight: 1.0,
                mean,
                cov,
            };
            let g = read.gaussian("").map_err(A::Error::custom)?;
            SpatialDensity::gaussian(g).map_err(density_error)
        };
        built.map_err(A::Error::custom)
    }
}

/// Exactly one of `{mean, cov}` ([`SpatialDensity::gaussian`]), `{mixture: [...]}`
/// ([`SpatialDensity::mixture`]) or `{particles, weights}` (`weights` optional, default
/// equal; [`SpatialDensity::particles`]). Two forms at once, or none, is a type error
/// (`invalid_type`); errors of the parts name them relative to the density (`.mixture[2].cov`,
/// `.particles[1]`).
impl<'de> Deserialize<'de> for SpatialDensity {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_struct("SpatialDensity", DENSITY_FIELDS, DensityVisitor)
    }
}

// --- bounds ---

use crate::bounds::{GaussianPrior, LinearGaussianSensor};

/// A matrix's entries row by row (the order the bounds' constructors take).
fn row_major(m: &DMatrix<f64>) -> Vec<f64> {
    m.transpose().as_slice().to_vec()
}

#[derive(Serialize, Deserialize)]
struct GaussianPriorRepr {
    mean: Vec<f64>,
    #[serde(with = "matrix")]
    cov: DMatrix<f64>,
}

through_constructor!(
    GaussianPrior,
    GaussianPriorRepr,
    |g| GaussianPriorRepr {
        mean: g.mean.clone(),
        cov: g.cov.clone(),
    },
    |r| GaussianPrior::new(&r.mean, &row_major(&r.cov))
);

#[derive(Serialize, Deserialize)]
struct LinearGaussianSensorRepr {
    detection_probability: f64,
    #[serde(with = "matrix")]
    gain: DMatrix<f64>,
    offset: Vec<f64>,
    #[serde(with = "matrix")]
    noise_cov: DMatrix<f64>,
}

through_constructor!(
    LinearGaussianSensor,
    LinearGaussianSensorRepr,
    |l| LinearGaussianSensorRepr {
        detection_probability: l.detection,
        gain: l.gain.clone(),
        offset: l.offset.clone(),
        noise_cov: l.noise.clone(),
    },
    |r| LinearGaussianSensor::new(
        r.detection_probability,
        &row_major(&r.gain),
        r.gain.ncols(),
        &r.offset,
        &row_major(&r.noise_cov)
    )
);

#[cfg(test)]
mod bounds_tests {
    use super::*;
    use alloc::string::ToString;

    #[test]
    fn eq63_prior_and_sensor_read_back_through_their_constructors() {
        let prior = GaussianPrior::new(&[1.0, 2.0], &[2.0, 0.5, 0.5, 1.0]).unwrap();
        let json = serde_json::to_string(&prior).unwrap();
        assert_eq!(json, r#"{"mean":[1.0,2.0],"cov":[[2.0,0.5],[0.5,1.0]]}"#);
        assert_eq!(serde_json::from_str::<GaussianPrior>(&json).unwrap(), prior);
        let sensor = LinearGaussianSensor::new(
            0.8,
            &[1.0, 0.5, 0.0, 2.0],
            2,
            &[0.1, 0.2],
            &[1.0, 0.0, 0.0, 3.0],
        )
        .unwrap();
        let json = serde_json::to_string(&sensor).unwrap();
        assert_eq!(
            serde_json::from_str::<LinearGaussianSensor>(&json).unwrap(),
            sensor
        );
        let bad = r#"{"mean":[0.0],"cov":[[-1.0]]}"#;
        assert!(serde_json::from_str::<GaussianPrior>(bad).is_err());
    }

    /// A prior of paper 002: a density on the line or a Gaussian state, one kind each.
    #[derive(Debug, PartialEq)]
    enum Prior {
        Line(Density1),
        Vector(GaussianPrior),
    }

    impl DensityOr for Prior {
        const KINDS: &'static [&'static str] = &[
            "gaussian",
            "uniform",
            "mixture",
            "table",
            "multivariate_gaussian",
        ];
        fn density(d: Density1) -> Self {
            Prior::Line(d)
        }
        fn other<'de, V: serde::de::VariantAccess<'de>>(
            kind: &str,
            v: V,
        ) -> Result<Self, V::Error> {
            match kind {
                "multivariate_gaussian" => v.newtype_variant().map(Prior::Vector),
                _ => Err(serde::de::Error::unknown_variant(kind, Self::KINDS)),
            }
        }
    }

    impl<'de> Deserialize<'de> for Prior {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            deserialize_density_or(d)
        }
    }

    #[test]
    fn eq63_a_prior_is_a_density_kind_or_its_own() {
        let line: Prior =
            serde_json::from_str(r#"{"gaussian": {"mean": 1, "variance": 4}}"#).unwrap();
        assert_eq!(line, Prior::Line(Density1::gaussian(1.0, 4.0).unwrap()));
        let table: Prior =
            serde_json::from_str(r#"{"table": {"x": [0, 1, 2], "density": [0, 1, 0]}}"#).unwrap();
        assert!(matches!(table, Prior::Line(Density1::Table { .. })));
        let vector: Prior = serde_json::from_str(
            r#"{"multivariate_gaussian": {"mean": [0, 1], "cov": [[2, 0.5], [0.5, 1]]}}"#,
        )
        .unwrap();
        assert_eq!(
            vector,
            Prior::Vector(GaussianPrior::new(&[0.0, 1.0], &[2.0, 0.5, 0.5, 1.0]).unwrap())
        );
        // a density's constructor error names the part at fault, relative to the value
        let e = serde_json::from_str::<Prior>(r#"{"gaussian": {"mean": 0, "variance": -1}}"#)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with(".gaussian.variance must be"), "{e}");
        let e = serde_json::from_str::<Prior>(r#"{"gausian": {}}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("multivariate_gaussian"), "{e}");
        // Density1 alone reads the same way and knows only its own kinds
        let d: Density1 = serde_json::from_str(r#"{"uniform": {"low": 0, "high": 1}}"#).unwrap();
        assert_eq!(d, Density1::uniform(0.0, 1.0).unwrap());
        assert!(serde_json::from_str::<Density1>(r#"{"multivariate_gaussian": {}}"#).is_err());
    }
}
