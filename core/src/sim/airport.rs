//! The airport example of Section V-C of `001_0f0df91eee9b30d5.txt`: a person of interest
//! walking through a concourse, tracked from natural-language reports "the person is near
//! anchor a" alone, with missed reports, false reports and exclusion regions (Figs. 6–8).

use alloc::string::String;
use alloc::vec::Vec;

use nalgebra::{DMatrix, DVector};

use crate::error::{Error, Result};
use crate::filters::{
    BernoulliFilterOptions, Birth, Clutter, ClutterDensity, Detection, LinearGaussianTransition,
    Splitting, default_mcmc_moves, default_particles, default_reduction,
};
use crate::gaussian::{Gaussian, GaussianMixture, normal};
use crate::math::fns;
use crate::math::rng::{index, poisson, seeded, uniform};
use crate::regions::{AxisBox, Region};

/// An anchor: a named landmark ("the taco stand") at a known position, with the radius
/// 2 d_a / 3 of its association disc 𝒜_a (eqs. (63)–(64)).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Anchor {
    /// The anchor's name ("taco stand").
    pub name: String,
    /// The anchor's position r_a = [x, y].
    pub position: [f64; 2],
    /// The radius 2 d_a / 3 of the anchor's association disc, d_a the distance to the nearest other anchor.
    pub radius: f64,
}

impl Anchor {
    /// 𝒜_a = {s : ‖s − r_a‖ ≤ 2 d_a / 3}, eq. (64).
    ///
    /// # Errors
    /// As [`Region::ball`] (a non-finite position or a radius that is not finite and > 0).
    pub fn disc(&self) -> Result<Region> {
        Region::ball(&self.position, self.radius, "anchor")
    }
}

/// The truth at one report time.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TruthPoint {
    /// The report time t = k T, in seconds.
    pub t: f64,
    /// The true state (x, y, ẋ, ẏ), position and velocity, eq. (61).
    pub state: [f64; 4],
}

/// One seeded run of the airport example (`airportScenario`).
///
/// # Layout (dimensionless distance units, seconds)
/// A concourse [0, 300] × [0, 30] with a west hall (x < 115), a connector corridor
/// 115 ≤ x ≤ 165 narrowed to 10 < y < 20, and an east hall (x > 165). Ten anchors, with
/// their association radii 2 d_a / 3:
///
/// ```text
///  a  name          position     d_a     radius
///  0  taco stand    ( 20,  8)   29.68   19.79
///  1  coffee shop   ( 45, 24)   29.68   19.79
///  2  bookstore     ( 70,  8)   29.68   19.79
///  3  gate A1       ( 95, 24)   29.68   19.79
///  4  gate B1       (180,  8)   25.61   17.08
///  5  pharmacy      (200, 24)   25.61   17.08
///  6  food court    (225, 10)   28.65   19.10
///  7  duty free     (250, 24)   25.61   17.08
///  8  restrooms     (270,  8)   23.32   15.55
///  9  gate B2       (290, 20)   23.32   15.55
/// ```
///
/// The field of view is S = ∪_a 𝒜_a (68): it covers both halls but not the middle of the
/// connector (about 115 < x < 163), where a walking person goes unreported for a few steps
/// (the misses "due to the object traveling outside detection bounds" of Fig. 7b). Four
/// exclusion rectangles (Fig. 6's grey areas):
///
/// ```text
///  seating island west   [ 30,  55] × [13, 17]
///  connector wall south  [115, 165] × [ 0, 10]
///  connector wall north  [115, 165] × [20, 30]
///  seating island east   [205, 240] × [14, 18]
/// ```
///
/// and, as a fifth exclusion region, the terminal's exterior (the complement of the
/// concourse): people do not walk through walls, and without it a filter whose motion model
/// carries the person past the end of the concourse keeps mass there that no report can
/// reach.
///
/// # Truth
/// A person walks at a constant cruising speed (uniform in [0.6, 1.0] per run) along a
/// jittered route of waypoints (west entrance → along the south of the west hall → through
/// the connector → along the south of the east hall → back along the north → …), simulated
/// in 1 s substeps: the velocity relaxes towards the waypoint direction with time constant
/// 8 s and receives the model's white acceleration noise (ϖ = 0.004); a substep that would
/// enter an exclusion rectangle or leave the concourse is replaced by sliding along the wall
/// (or stopping), so the truth never enters one or leaves the concourse. The truth is reported every T = 15 s.
///
/// # Reports
/// At step k, if the person is in S, with probability p_D = 0.9 one true report names the
/// nearest anchor whose disc contains them; a Poisson(λ_c = 0.25) number of false reports
/// name anchors uniformly at random (c̃ = 1/10 per anchor). Reports are listed by anchor
/// index.
///
/// # Filter configuration
/// `config` (for both filters): the NCV model (70)–(71) with T = 15, ϖ = 0.004; p_S = 0.99;
/// r_{0|0} = 0.5 and p_{0|0} = N((5, 15, 0.5, 0), diag(25, 25, 0.25, 0.25)), the west
/// entrance; birth p_b = 0.05 with b(x) anywhere on the concourse (equal weights, one
/// component per anchor: N((r_a, 0, 0), diag(ρ_a², ρ_a², 0.5, 0.5)), ρ_a the disc radius), so
/// that a filter that has lost the person re-acquires them; p_D = 0.9 on S; λ_c = 0.25,
/// c̃ = 1/10; the four exclusions; the default splitting and reduction.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AirportScenario {
    /// The ten anchors, in report-index order.
    pub anchors: Vec<Anchor>,
    /// The four exclusion rectangles, as boxes.
    pub exclusion_boxes: Vec<AxisBox>,
    /// The concourse [0, 300] × [0, 30] (`concourse`): its exterior is the fifth exclusion.
    pub concourse: AxisBox,
    /// The exclusion regions (`exclusions`): the four rectangles, then the terminal's
    /// exterior (the complement of the concourse).
    pub exclusions: Vec<Region>,
    /// The field of view S = ∪_a 𝒜_a, the union of the anchors' discs (`fov`).
    pub fov: Region,
    /// The report interval T = 15 s (`dt`).
    pub dt: f64,
    /// The configuration of both filters (`config`).
    pub config: BernoulliFilterOptions,
    /// The truth at t = T, 2T, … (`truth`).
    pub truth: Vec<TruthPoint>,
    /// The anchor indices reported at each step (`reports`), ascending.
    pub reports: Vec<Vec<usize>>,
    /// The anchor of the true report at each step, `None` when the person was missed
    /// (outside S or not detected) (`trueReports`).
    pub true_reports: Vec<Option<usize>>,
    /// Whether the person was inside S at each step (`inFov`).
    pub in_fov: Vec<bool>,
}

/// The anchors (name, position) of the layout.
const ANCHORS: [(&str, [f64; 2]); 10] = [
    ("taco stand", [20.0, 8.0]),
    ("coffee shop", [45.0, 24.0]),
    ("bookstore", [70.0, 8.0]),
    ("gate A1", [95.0, 24.0]),
    ("gate B1", [180.0, 8.0]),
    ("pharmacy", [200.0, 24.0]),
    ("food court", [225.0, 10.0]),
    ("duty free", [250.0, 24.0]),
    ("restrooms", [270.0, 8.0]),
    ("gate B2", [290.0, 20.0]),
];

/// The exclusion rectangles ([min], [max]).
const EXCLUSIONS: [([f64; 2], [f64; 2]); 4] = [
    ([30.0, 13.0], [55.0, 17.0]),
    ([115.0, 0.0], [165.0, 10.0]),
    ([115.0, 20.0], [165.0, 30.0]),
    ([205.0, 14.0], [240.0, 18.0]),
];

/// The concourse [0, 300] × [0, 30].
const CONCOURSE: ([f64; 2], [f64; 2]) = ([0.0, 0.0], [300.0, 30.0]);

/// The route (before jitter); after the last waypoint it starts again at index 1.
const ROUTE: [[f64; 2]; 13] = [
    [25.0, 7.0],
    [62.0, 7.0],
    [105.0, 15.0],
    [170.0, 15.0],
    [198.0, 8.0],
    [246.0, 8.0],
    [288.0, 15.0],
    [250.0, 23.0],
    [205.0, 23.0],
    [170.0, 15.0],
    [105.0, 15.0],
    [62.0, 23.0],
    [25.0, 23.0],
];

/// T of the example, seconds.
pub const AIRPORT_DT: f64 = 15.0;
/// ϖ of the example.
pub const AIRPORT_NOISE: f64 = 0.004;
/// The paper's number of report times (15 minutes at T = 15 s).
pub const AIRPORT_PAPER_STEPS: usize = 60;

/// The steps of [`airport_scenario`] when a user's options omit them: [`AIRPORT_PAPER_STEPS`].
pub const fn default_steps() -> usize {
    AIRPORT_PAPER_STEPS
}

/// Options of [`airport_scenario`] (`airportScenario`, the airport example of LeGrand &
/// Ferrari, "Split Happens! Imprecise and negative information in Gaussian mixture random
/// finite set filtering" (paper 001), Section V-C); every field optional, by default fresh
/// entropy and 60 steps ([`AirportScenarioOptions::default`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default)
)]
pub struct AirportScenarioOptions {
    /// The seed (integer in [0, 2^53 − 1]); omitted: fresh entropy.
    pub seed: Option<u64>,
    /// Report times (default 60, at most 2000).
    pub steps: usize,
}

impl Default for AirportScenarioOptions {
    /// No seed (the caller draws one) and [`default_steps`].
    fn default() -> Self {
        Self {
            seed: None,
            steps: default_steps(),
        }
    }
}
/// The largest number of steps [`airport_scenario`] simulates.
pub const MAX_AIRPORT_STEPS: usize = 2000;

/// The anchors of the layout with their radii 2 d_a / 3.
pub fn airport_anchors() -> Vec<Anchor> {
    ANCHORS
        .iter()
        .enumerate()
        .map(|(a, (name, p))| {
            let d = ANCHORS
                .iter()
                .enumerate()
                .filter(|(b, _)| *b != a)
                .map(|(_, (_, q))| fns::sqrt(sq(p[0] - q[0]) + sq(p[1] - q[1])))
                .fold(f64::INFINITY, f64::min);
            Anchor {
                name: (*name).into(),
                position: *p,
                radius: 2.0 * d / 3.0,
            }
        })
        .collect()
}

#[inline]
fn sq(x: f64) -> f64 {
    x * x
}

fn blocked(p: [f64; 2], boxes: &[AxisBox]) -> bool {
    let (lo, hi) = CONCOURSE;
    !(p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1])
        || boxes.iter().any(|b| b.contains(&p))
}

/// The airport example: `steps` report times (the paper: 60, i.e. 15 minutes) of a seeded
/// run ([`AirportScenario`] documents the layout, the truth and the reports).
///
/// # Errors
/// [`Error::OutOfRange`] naming `steps` above [`MAX_AIRPORT_STEPS`].
///
/// # Examples
/// ```
/// use fisst::sim::airport::airport_scenario;
/// let s = airport_scenario(7, 60)?;
/// assert_eq!((s.anchors.len(), s.reports.len(), s.truth.len()), (10, 60, 60));
/// assert!(s.truth.iter().all(|t| !s.exclusions.iter().any(|e| e.contains(&t.state))));
/// # Ok::<(), fisst::Error>(())
/// ```
pub fn airport_scenario(seed: u64, steps: usize) -> Result<AirportScenario> {
    Error::check_range("steps", steps, 0, MAX_AIRPORT_STEPS)?;
    let anchors = airport_anchors();
    let discs: Vec<Region> = anchors.iter().map(Anchor::disc).collect::<Result<_>>()?;
    let fov = Region::union(discs.clone(), "fov")?;
    let exclusion_boxes: Vec<AxisBox> = EXCLUSIONS
        .iter()
        .enumerate()
        .map(|(i, (lo, hi))| AxisBox::new(lo, hi, &alloc::format!("exclusions[{i}]")))
        .collect::<Result<_>>()?;
    let mut exclusions: Vec<Region> = exclusion_boxes.iter().cloned().map(Region::from).collect();
    // The terminal's exterior: the complement of the concourse.
    exclusions.push(Region::complement(Region::axis_box(
        &CONCOURSE.0,
        &CONCOURSE.1,
        "exclusions[4]",
    )?));

    // Truth.
    let mut rng = seeded(seed);
    let speed = 0.6 + 0.4 * uniform(&mut rng);
    let route: Vec<[f64; 2]> = ROUTE
        .iter()
        .map(|w| {
            [
                w[0] + 4.0 * uniform(&mut rng) - 2.0,
                w[1] + 4.0 * uniform(&mut rng) - 2.0,
            ]
        })
        .collect();
    let mut pos = [5.0, 15.0];
    let mut target = 0usize;
    let dir = |p: [f64; 2], w: [f64; 2]| {
        let (dx, dy) = (w[0] - p[0], w[1] - p[1]);
        let d = fns::sqrt(dx * dx + dy * dy).max(1e-9);
        [dx / d, dy / d]
    };
    let d0 = dir(pos, route[0]);
    let mut vel = [speed * d0[0], speed * d0[1]];
    let substeps = 15;
    let h = AIRPORT_DT / substeps as f64;
    let tau = 8.0;
    let sd = fns::sqrt(AIRPORT_NOISE * h);
    let mut truth = Vec::with_capacity(steps);
    let mut reports = Vec::with_capacity(steps);
    let mut true_reports = Vec::with_capacity(steps);
    let mut in_fov = Vec::with_capacity(steps);
    for k in 1..=steps {
        for _ in 0..substeps {
            let w = route[target];
            if sq(w[0] - pos[0]) + sq(w[1] - pos[1]) < 9.0 {
                target = if target + 1 == route.len() {
                    1
                } else {
                    target + 1
                };
            }
            let d = dir(pos, route[target]);
            for i in 0..2 {
                vel[i] += (speed * d[i] - vel[i]) * (h / tau) + sd * normal::sample(&mut rng);
            }
            let next = [pos[0] + h * vel[0], pos[1] + h * vel[1]];
            if !blocked(next, &exclusion_boxes) {
                pos = next;
            } else if !blocked([next[0], pos[1]], &exclusion_boxes) {
                pos = [next[0], pos[1]];
                vel[1] = 0.0;
            } else if !blocked([pos[0], next[1]], &exclusion_boxes) {
                pos = [pos[0], next[1]];
                vel[0] = 0.0;
            } else {
                vel = [0.0, 0.0];
            }
        }
        truth.push(TruthPoint {
            t: k as f64 * AIRPORT_DT,
            state: [pos[0], pos[1], vel[0], vel[1]],
        });
        // Reports.
        let inside = fov.contains(&pos);
        in_fov.push(inside);
        let mut scan = Vec::new();
        let mut true_report = None;
        let detected = uniform(&mut rng) < 0.9;
        if inside && detected {
            let mut best: Option<(f64, usize)> = None;
            for (a, disc) in discs.iter().enumerate() {
                if disc.contains(&pos) {
                    let p = anchors[a].position;
                    let d2 = sq(p[0] - pos[0]) + sq(p[1] - pos[1]);
                    if best.is_none_or(|(b, _)| d2 < b) {
                        best = Some((d2, a));
                    }
                }
            }
            if let Some((_, a)) = best {
                scan.push(a);
                true_report = Some(a);
            }
        }
        for _ in 0..poisson(&mut rng, 0.25, 1000) {
            scan.push(index(&mut rng, anchors.len()));
        }
        crate::math::sort::sort_by(&mut scan, |a, b| a.cmp(b));
        reports.push(scan);
        true_reports.push(true_report);
    }

    let config = airport_config(fov.clone(), exclusions.clone(), &anchors)?;
    Ok(AirportScenario {
        anchors,
        exclusion_boxes,
        concourse: AxisBox::new(&CONCOURSE.0, &CONCOURSE.1, "concourse")?,
        exclusions,
        fov,
        dt: AIRPORT_DT,
        config,
        truth,
        reports,
        true_reports,
        in_fov,
    })
}

/// The filter configuration of the example (see [`AirportScenario`]).
fn airport_config(
    fov: Region,
    exclusions: Vec<Region>,
    anchor_list: &[Anchor],
) -> Result<BernoulliFilterOptions> {
    let anchors = anchor_list.len();
    let entrance = Gaussian::new(
        DVector::from_column_slice(&[5.0, 15.0, 0.5, 0.0]),
        DMatrix::from_diagonal(&DVector::from_column_slice(&[25.0, 25.0, 0.25, 0.25])),
        "mixture[0]",
    )?;
    let mixture = GaussianMixture::new(alloc::vec![(1.0, entrance)], "mixture")?;
    // Birth anywhere on the concourse: one component per anchor, the disc's spread in
    // position and walking speeds in velocity, so that a filter that has lost the person
    // re-acquires them from the next reports.
    let mut birth = Vec::with_capacity(anchor_list.len());
    for (a, anchor) in anchor_list.iter().enumerate() {
        let r2 = anchor.radius * anchor.radius;
        birth.push((
            1.0 / anchor_list.len() as f64,
            Gaussian::new(
                DVector::from_column_slice(&[anchor.position[0], anchor.position[1], 0.0, 0.0]),
                DMatrix::from_diagonal(&DVector::from_column_slice(&[r2, r2, 0.5, 0.5])),
                &alloc::format!("birth.mixture[{a}]"),
            )?,
        ));
    }
    let birth = GaussianMixture::new(birth, "birth.mixture")?;
    Ok(BernoulliFilterOptions {
        existence: 0.5,
        mixture: mixture.clone(),
        transition: LinearGaussianTransition::nearly_constant_velocity(
            2,
            AIRPORT_DT,
            AIRPORT_NOISE,
        )?,
        survival: 0.99,
        birth: Birth::new(0.05, birth)?,
        position_dims: 2,
        detection: Detection::new(0.9, Some(fov))?,
        clutter: Clutter::new(0.25, ClutterDensity::Constant(1.0 / anchors as f64))?,
        likelihood: None,
        splitting: Splitting::default(),
        reduction: default_reduction(),
        exclusions,
    })
}

impl AirportScenario {
    /// The report regions of step k (0-based): the discs of the reported anchors.
    ///
    /// # Panics
    /// If `k >= self.reports.len()`.
    pub fn report_regions(&self, k: usize) -> Vec<Region> {
        self.reports[k]
            .iter()
            .filter_map(|&a| self.anchors[a].disc().ok())
            .collect()
    }
}

/// The filter configuration of the airport example as a caller passes it to either filter
/// (`GmBernoulliFilter`, `ParticleBernoulliFilter`): the example's model of Section V-C of
/// `001_…` ([`AirportScenario::config`]) with the particle filter's size, moves and seed.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AirportFilterConfig {
    /// The initial existence probability r_{0|0} ∈ [0, 1].
    pub existence: f64,
    /// The initial spatial density p_{0|0}, a Gaussian mixture.
    #[cfg_attr(feature = "serde", serde(with = "crate::serde_shapes::components"))]
    pub mixture: GaussianMixture,
    /// The motion model (70)–(71): transition matrix F and process noise covariance Q.
    pub transition: LinearGaussianTransition,
    /// The survival probability p_S ∈ [0, 1]: the probability that the person stays one more
    /// step.
    pub survival: f64,
    /// Object birth: the birth probability p_b and birth density b(x).
    pub birth: Birth,
    /// The number n_s of position components: 2 (x, y).
    pub position_dims: usize,
    /// Detection: detection probability p_D = 0.9 inside the field of view S.
    pub detection: Detection,
    /// Clutter: rate λ_c = 0.25 false reports per scan, density c̃ = 1/10 (one of ten
    /// anchors).
    pub clutter: Clutter,
    /// The exclusion regions the person cannot occupy.
    pub exclusions: Vec<Region>,
    /// Particle filter: the number of particles N, 5000 (the filters' default).
    pub particles: usize,
    /// Particle filter: MCMC moves per update, 1 (the filters' default).
    pub mcmc_moves: usize,
    /// The scenario's seed, for the particle filter.
    pub seed: u64,
}

/// The airport example of Section V-C of `001_…` (Figs. 6–8) as a result
/// (`airportScenario`): [`AirportScenario`] with the concourse as a region, the filter
/// configuration ready for both filters, and the seed.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct AirportScenarioReport {
    /// The ten anchors, in report-index order.
    pub anchors: Vec<Anchor>,
    /// The exclusion regions (four rectangles, then the exterior of the concourse).
    pub exclusions: Vec<Region>,
    /// The concourse, a box [0, 300] × [0, 30].
    pub concourse: Region,
    /// The field of view S: the union of the anchors' association discs.
    pub fov: Region,
    /// The report interval T = 15 s.
    pub dt: f64,
    /// The configuration of both filters.
    pub config: AirportFilterConfig,
    /// The person's true state at each report time.
    pub truth: Vec<TruthPoint>,
    /// The reported anchor indices per step.
    pub reports: Vec<Vec<usize>>,
    /// The anchor of the true report per step (`None`: missed).
    pub true_reports: Vec<Option<usize>>,
    /// Whether the person was in S per step.
    pub in_fov: Vec<bool>,
    /// The seed used (the option's, or the fresh one drawn).
    pub seed: u64,
}

impl AirportScenarioReport {
    /// [`airport_scenario`]`(seed, steps)` as a report.
    ///
    /// # Errors
    /// Those of [`airport_scenario`] (`steps` above [`MAX_AIRPORT_STEPS`]).
    pub fn new(seed: u64, steps: usize) -> Result<Self> {
        let sc = airport_scenario(seed, steps)?;
        let c = sc.config;
        Ok(Self {
            anchors: sc.anchors,
            exclusions: sc.exclusions,
            concourse: Region::from(sc.concourse),
            fov: sc.fov,
            dt: sc.dt,
            config: AirportFilterConfig {
                existence: c.existence,
                mixture: c.mixture,
                transition: c.transition,
                survival: c.survival,
                birth: c.birth,
                position_dims: c.position_dims,
                detection: c.detection,
                clutter: c.clutter,
                exclusions: c.exclusions,
                particles: default_particles(),
                mcmc_moves: default_mcmc_moves(),
                seed,
            },
            truth: sc.truth,
            reports: sc.reports,
            true_reports: sc.true_reports,
            in_fov: sc.in_fov,
            seed,
        })
    }
}
