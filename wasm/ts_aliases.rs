//! The contract's names for the core's types (`export type GospaResult = GospaReport;`), read by
//! `build.rs`, which writes each alias, with its doc, into the declarations of every part that
//! reaches one of its two names (and then declares the type it names). The left name is
//! declared by the binding (the generator names it, never generates it); the right one is the
//! type it stands for: a core type.
//!
//! `(name, type, doc)`: a doc that does not end in a period is followed by ": the core's
//! `type`."; `\n` breaks its lines. Every name here is published: keep it, even if no test
//! uses it.
#[rustfmt::skip]
pub const ALIASES: &[(&str, &str, &str)] = &[
    // bernoulli
    ("BernoulliCosts", "Costs", "Costs of the loss (7)"),
    ("BernoulliLossCurveOptions", "LossCurveOptions", "Options of `bernoulliLossCurve`"),
    ("BernoulliLossCurveResult", "LossCurve", "Result of `bernoulliLossCurve`"),
    ("BernoulliThresholdCurveOptions", "ThresholdCurveOptions", "Options of `bernoulliThresholdCurve`"),
    ("BernoulliDensity", "SpatialDensity", "The spatial density of a Bernoulli"),
    ("MmucEstimateOptions", "MmucOptions", "Options of `mmucEstimate`"),
    ("MmucEstimateResult", "MmucEstimate", "Result of `mmucEstimate`"),
    ("MultiBernoulliPointEstimateOptions", "MultiBernoulliPointOptions", "Options of `multiBernoulliPointEstimate`"),
    ("MultiBernoulliPointEstimateResult", "MultiBernoulliReport", "Result of `multiBernoulliPointEstimate`"),
    ("BernoulliEstimateResult", "BernoulliReport", "Result of `bernoulliEstimate`"),
    // bernoulli_filters
    ("ReductionOptionsJs", "ReductionOptions", "The reduction after the update (the options of `reduceMixture`): the core's\n`ReductionOptions`. Omitted: prune 1e-6, merge within Mahalanobis distance 2 (U = 4),\nRunnalls to 100."),
    ("Transition", "TransitionRows", "The linear-Gaussian transition N(x; F x′, Q) (eq. (44) of paper 001): the core's\n`TransitionRows`."),
    ("LikelihoodOptions", "LikelihoodRows", "The linear-Gaussian likelihood N(z; H x, R) of vector measurements: the core's\n`LikelihoodRows`."),
    ("BirthOptions", "Birth", "Object birth"),
    ("DetectionOptions", "Detection", "Object detection"),
    ("ClutterOptions", "Clutter", "Poisson false reports: rate λ_c and density c̃(ζ)"),
    ("ClutterDensityOption", "ClutterDensity", "c̃(ζ): one number for every report, or one per report"),
    ("GmBernoulliResult", "GmBernoulli", "Result of `gmBernoulliPredict`: the predicted Bernoulli"),
    ("GmBernoulliUpdateResult", "GmBernoulliUpdate", "Result of `gmBernoulliUpdate`: the posterior Bernoulli"),
    ("FilterEstimateResult", "FilterEstimateReport", "The result of the filters' `estimate()`: the posterior existence, MMSE state and\ncovariance"),
    ("AirportScenarioResult", "AirportScenarioReport", "Result of `airportScenario`: the airport example of LeGrand & Ferrari, \"Split Happens!\nImprecise and negative information in Gaussian mixture random finite set filtering\" (paper\n001), Section V-C"),
    ("AirportConfig", "AirportFilterConfig", "The filter configuration of the example, ready for both classes (a\n`BernoulliFilterConfig`)"),
    ("AirportBirth", "Birth", "Object birth of the example"),
    ("AirportDetection", "Detection", "Detection of the example"),
    ("AirportClutter", "Clutter", "Clutter (false reports) of the example"),
    ("AnchorOut", "Anchor", "An anchor of the airport example"),
    ("TruthOut", "TruthPoint", "The truth at one report time"),
    // bounds
    ("JdeBoundNoClutterOptions", "NoClutterOptions", "Options of `jdeBoundNoClutter`"),
    ("JdeBoundNoClutterResult", "NoClutterBound", "Result of `jdeBoundNoClutter`"),
    ("GaussianFisherInformationOptions", "GaussianInformationOptions", "Options of `gaussianFisherInformation`"),
    ("GaussianFisherInformationResult", "GaussianInformation", "Result of `gaussianFisherInformation`"),
    ("JdeSequentialBoundOptions", "SequentialOptions", "Options of `jdeSequentialBound`"),
    ("JdeSequentialBoundResult", "SequentialBound", "Result of `jdeSequentialBound`"),
    ("JdeExample2Options", "Example2Options", "Options of `jdeExample2`"),
    ("JdeExample2Result", "Example2", "Result of `jdeExample2`: the core's `Example2`. Neither number is a lower bound where the\nestimation term matters: p_1 does not vanish at x = 1 (see `jdeExample2Regularity`)."),
    ("JdeExample2RegularityResult", "Example2Regularity", "Result of `jdeExample2Regularity`"),
    ("DensityShape", "Density1", "A 1D density: `{ gaussian: { mean, variance } }`, `{ uniform: { low, high } }`,\n`{ mixture: [{ weight, mean, variance }, …] }` (1 to 1,000 components) or\n`{ table: { x, density } }`"),
    ("DetectionTableShape", "DetectionTable", "A tabulated detection probability P_o(x)"),
    ("DetectionShape", "JdeDetectionOptions", "The detection probability P_o(x)"),
    ("PriorShape", "PriorOptions", "The prior f of `jdeBound`"),
    ("MonteCarloPriorShape", "MonteCarloPrior", "The state of `jdeMonteCarlo`"),
    ("ObservationShape", "ObservationOptions", "The observation of `jdeBound` and `jdeMonteCarlo`"),
    ("FalseAlarmShape", "JdeFalseAlarm", "Model I's false observations"),
    ("ClutterShape", "JdeClutter", "Model II's Poisson clutter"),
    ("JdeMonteCarloOptions", "JdeMonteCarloRequest", "Options of `jdeMonteCarlo`"),
    ("MeasurementModel", "JdeModel", "The measurement model of `jdeBound` and `jdeMonteCarlo`"),
    ("EmptyRuleShape", "EmptyRule", "The rule of `jdeMonteCarlo` on Z = ∅"),
    ("JdeBoundResult", "JdeBoundReport", "Result of `jdeBound`"),
    ("JdeMonteCarloResult", "JdeMonteCarlo", "Result of `jdeMonteCarlo`"),
    // control
    ("MultiObjectLikelihoodResult", "ParticleLikelihood", "Result of `multiObjectLikelihood`"),
    ("SensorControlRunOptions", "ControlOptions", "Options of `new SensorControlRun`"),
    ("ControlStep", "StepOutcome", "Result of `SensorControlRun.step()`"),
    ("ActionOut", "Action", "The action u_k (23)"),
    ("ControlEstimate", "SetEstimate", "The point estimate of Sec. 5.2"),
    ("CompareSchemesResult", "Comparison", "Result of `compareSchemes`"),
    ("SchemeComparison", "SchemeSummary", "One scheme of `compareSchemes`"),
    ("MeanOverRuns", "MeanSeries", "A mean over runs per step, with its standard error"),
    // fov
    ("PlacementSceneOptions", "SceneOptions", "Options of `placementScene`, every one optional"),
    ("PlacementSceneResult", "PlacementScene", "Result of `placementScene`: the core's `PlacementScene`; `multiBernoulli` is ready for\n`fovCardinality` and `fovVarianceMap`."),
    // metrics
    ("GospaResult", "GospaReport", "Result of `gospa`"),
    ("OspaResult", "OspaDecomposition", "Result of `ospa`"),
    ("GospaSeriesResult", "GospaSeries", "Result of `gospaSeries`"),
    ("OspaSeriesResult", "OspaSeries", "Result of `ospaSeries`"),
    ("LinearAssignmentResult", "Assignment", "Result of `linearAssignment`"),
    // multi_bernoulli
    ("MbOptimalEstimateResult", "MbEstimate", "Result of `mbOptimalEstimate`"),
    ("MbAlternativeEstimateResult", "AlternativeEstimate", "Result of `mbAlternativeEstimate`"),
    ("MbDecisionMapOptions", "DecisionMapOptions", "Options of `mbDecisionMap`"),
    ("MbDecisionMapResult", "DecisionMap", "Result of `mbDecisionMap`"),
    ("MbIdenticalComponentCountsOptions", "IdenticalComponentCountsOptions", "Options of `mbIdenticalComponentCounts`"),
    ("MbIdenticalComponentCountsResult", "IdenticalComponentCounts", "Result of `mbIdenticalComponentCounts`"),
    // splitting
    ("SplitLibraryResult", "SplitLibraryReport", "Result of `splitLibrary`"),
    ("SplitForRegionsResult", "SplitForRegionsReport", "Result of `splitForRegions`: the split mixture and its mean-based partition"),
    ("NegativeInformationStep", "NegativeInformationStepReport", "One predict → split → non-detection update cycle of the Fig. 5 scenario of LeGrand &\nFerrari, \"Split Happens! Imprecise and negative information in Gaussian mixture random finite\nset filtering\" (paper 001)"),
    ("NegativeInformationScenario", "NegativeInformationReport", "Result of `negativeInformationScenario`: the Fig. 5 scenario of paper 001 (FoV, initial\nmixture over (x, y, ẋ, ẏ) and the three steps)"),
];
