#!/usr/bin/env python3
"""Bernoulli filters side by side: Stone Soup's Bernoulli particle filter
(BernoulliParticlePredictor + BernoulliParticleUpdater with systematic resampling and its
MCMC regulariser) against fisst's GM Bernoulli filter and its particle Bernoulli filter
(natively, through benches/src/bin/bernoulli_filter_timing.rs), on the same seeded
linear-Gaussian vector-measurement scenario with Poisson clutter.

Scenario: 2D nearly-constant-velocity target (T = 1, q = 0.05), positions measured with
R = I, p_D = 0.9, clutter Poisson(0.5) per scan uniform over [-100, 100]^2, p_S = 0.99,
birth p_b = 0.05 with density N((-50, -50, 1, 1), diag(25, 25, 0.25, 0.25)); the target exists
for steps 10..59 of 80. Both particle filters use 5,000 particles, 500 birth particles and one
MCMC move. Reported: time per step (median of REPS runs), mean |r - 1{exists}| over all steps,
position RMSE of the MMSE estimate while the target exists, the mean existence over the empty
scans after the target died, and the empty-scan check: r = 0.8, p_D = 0.9, one scan with no
detection (the Bernoulli update gives 0.8 * 0.1 / (1 - 0.8 * 0.9) = 0.2857; Stone Soup 1.9.1's
updater skips the update when a scan is empty, `if any(hypotheses):`, and returns 0.8).

    python3 benches/bernoulli_vs_stonesoup.py     (creates benches/.venv with stonesoup 1.9.1)
"""
import json, os, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
VENV = os.path.join(HERE, ".venv")
STONESOUP = "stonesoup==1.9.1"


def ensure_venv():
    """Re-exec inside benches/.venv with stonesoup installed."""
    py = os.path.join(VENV, "bin", "python")
    if os.path.realpath(sys.prefix) == os.path.realpath(VENV):
        return
    if not os.path.exists(py):
        subprocess.run([sys.executable, "-m", "venv", VENV], check=True)
    try:
        subprocess.run([py, "-c", "import stonesoup"], check=True, capture_output=True)
    except subprocess.CalledProcessError:
        subprocess.run([py, "-m", "pip", "install", "-q", STONESOUP], check=True)
    os.execv(py, [py] + sys.argv)


ensure_venv()

import numpy as np  # noqa: E402
from datetime import datetime, timedelta  # noqa: E402
from stonesoup.models.transition.linear import (  # noqa: E402
    CombinedLinearGaussianTransitionModel, ConstantVelocity)
from stonesoup.models.measurement.linear import LinearGaussian  # noqa: E402
from stonesoup.predictor.particle import BernoulliParticlePredictor  # noqa: E402
from stonesoup.updater.particle import BernoulliParticleUpdater  # noqa: E402
from stonesoup.resampler.particle import SystematicResampler  # noqa: E402
from stonesoup.regulariser.particle import MCMCRegulariser  # noqa: E402
from stonesoup.sampler.detection import DetectionSampler  # noqa: E402
from stonesoup.types.array import StateVector, StateVectors  # noqa: E402
from stonesoup.types.detection import Detection, MissedDetection  # noqa: E402
from stonesoup.types.hypothesis import SingleHypothesis  # noqa: E402
from stonesoup.types.multihypothesis import MultipleHypothesis  # noqa: E402
from stonesoup.types.state import BernoulliParticleState, ParticleState  # noqa: E402

STEPS, BORN, DIES = 80, 10, 60
Q, PD, PS, PB = 0.05, 0.9, 0.99, 0.05
RATE, SIDE = 0.5, 200.0
DENSITY = 1.0 / (SIDE * SIDE)
N, NB, MOVES, REPS = 5000, 500, 1, 3
BIRTH_MEAN = [-50.0, -50.0, 1.0, 1.0]           # fisst order (x, y, vx, vy)
BIRTH_VAR = [25.0, 25.0, 0.25, 0.25]
F = [[1, 0, 1, 0], [0, 1, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]
QM = [[Q / 3, 0, Q / 2, 0], [0, Q / 3, 0, Q / 2], [Q / 2, 0, Q, 0], [0, Q / 2, 0, Q]]
H = [[1, 0, 0, 0], [0, 1, 0, 0]]
R = [[1.0, 0.0], [0.0, 1.0]]
# Stone Soup orders the state (x, vx, y, vy).
TO_SS = [0, 2, 1, 3]


def scenario(seed=2026):
    rng = np.random.default_rng(seed)
    truth, scans = [], []
    x = np.array([-50.0, -50.0, 1.0, 1.2])
    Fm, Qm = np.array(F, float), np.array(QM, float)
    for k in range(STEPS):
        exists = BORN <= k < DIES
        if exists and k > BORN:
            x = Fm @ x + rng.multivariate_normal(np.zeros(4), Qm)
        truth.append(x.copy() if exists else None)
        scan = []
        if exists and rng.uniform() < PD:
            scan.append((x[:2] + rng.normal(size=2)).tolist())
        for _ in range(rng.poisson(RATE)):
            scan.append(rng.uniform(-SIDE / 2, SIDE / 2, size=2).tolist())
        rng.shuffle(scan)
        scans.append(scan)
    return truth, scans


class FixedBirthSampler(DetectionSampler):
    """Birth particles from the known birth density (as fisst's filters use), ignoring the
    detections."""

    def sample(self, detections, **kwargs):
        m = np.array(BIRTH_MEAN)[TO_SS]
        sd = np.sqrt(np.array(BIRTH_VAR)[TO_SS])
        pts = m[:, None] + sd[:, None] * np.random.normal(size=(4, NB))
        return ParticleState(StateVectors(pts), weight=np.full(NB, 1.0 / NB))


def stonesoup_models():
    transition = CombinedLinearGaussianTransitionModel([ConstantVelocity(Q), ConstantVelocity(Q)])
    measurement = LinearGaussian(ndim_state=4, mapping=(0, 2), noise_covar=np.array(R))
    predictor = BernoulliParticlePredictor(
        transition_model=transition, birth_probability=PB, survival_probability=PS,
        birth_sampler=FixedBirthSampler())
    updater = BernoulliParticleUpdater(
        measurement_model=measurement, resampler=SystematicResampler(),
        regulariser=MCMCRegulariser(transition_model=transition) if MOVES else None,
        clutter_rate=RATE, clutter_distribution=DENSITY, detection_probability=PD,
        nsurv_particles=N)
    return predictor, updater, measurement


def stonesoup_prior(existence, t0):
    m = np.array(BIRTH_MEAN)[TO_SS]
    sd = np.sqrt(np.array(BIRTH_VAR)[TO_SS])
    pts = m[:, None] + sd[:, None] * np.random.normal(size=(4, N))
    return BernoulliParticleState(StateVectors(pts), weight=np.full(N, 1.0 / N),
                                  existence_probability=existence, timestamp=t0)


def run_stonesoup(scans, seed):
    np.random.seed(seed)
    predictor, updater, measurement = stonesoup_models()
    t0 = datetime(2026, 1, 1)
    prior = stonesoup_prior(0.5, t0)
    existence, means = [], []
    start = time.perf_counter()
    for k, scan in enumerate(scans):
        t = t0 + timedelta(seconds=k + 1)
        prediction = predictor.predict(prior, timestamp=t)
        if scan:
            dets = [Detection(StateVector(z), timestamp=t, measurement_model=measurement)
                    for z in scan]
            hyps = MultipleHypothesis([SingleHypothesis(prediction, d) for d in dets])
        else:
            hyps = MultipleHypothesis([SingleHypothesis(prediction, MissedDetection(timestamp=t))])
        prior = updater.update(hyps)
        existence.append(float(prior.existence_probability))
        mean = np.asarray(prior.mean, float).ravel()
        means.append([mean[0], mean[2], mean[1], mean[3]])
    return (time.perf_counter() - start) / len(scans), existence, means


def stonesoup_empty_scan():
    """r = 0.8, p_D = 0.9, no detection: what Stone Soup's updater returns."""
    np.random.seed(1)
    _, updater, _ = stonesoup_models()
    t = datetime(2026, 1, 1)
    prior = stonesoup_prior(0.8, t)
    hyps = MultipleHypothesis([SingleHypothesis(prior, MissedDetection(timestamp=t))])
    return float(updater.update(hyps).existence_probability)


def metrics(truth, existence, means):
    exists = [t is not None for t in truth]
    e_err = float(np.mean([abs(r - (1.0 if x else 0.0)) for r, x in zip(existence, exists)]))
    sq = [(m[0] - t[0]) ** 2 + (m[1] - t[1]) ** 2 for m, t in zip(means, truth) if t is not None]
    after = [r for k, (r, x) in enumerate(zip(existence, exists)) if k >= DIES]
    return e_err, float(np.sqrt(np.mean(sq))), float(np.mean(after))


def run_fisst(scans):
    subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "bernoulli_filter_timing"],
                   cwd=HERE, check=True)
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(HERE, "target"))
    binary = os.path.join(target, "release", "bernoulli_filter_timing")
    spec = {
        "F": F, "Q": QM, "H": H, "R": R, "detection": PD, "survival": PS,
        "birth": {"probability": PB, "mean": BIRTH_MEAN, "cov": np.diag(BIRTH_VAR).tolist()},
        "initial": {"existence": 0.5, "mean": BIRTH_MEAN, "cov": np.diag(BIRTH_VAR).tolist()},
        "clutter": {"rate": RATE, "density": DENSITY},
        "particles": N, "birthParticles": NB, "mcmcMoves": MOVES, "seed": 7, "reps": REPS,
        "scans": scans,
    }
    with tempfile.TemporaryDirectory() as d:
        inp, out = os.path.join(d, "in.json"), os.path.join(d, "out.json")
        with open(inp, "w") as f:
            json.dump(spec, f)
        subprocess.run([binary, inp, out], check=True)
        with open(out) as f:
            return json.load(f)


def main():
    truth, scans = scenario()
    empties = sum(1 for s in scans if not s)
    print(f"scenario: {STEPS} steps, target exists for steps {BORN}..{DIES - 1}, "
          f"{sum(len(s) for s in scans)} detections, {empties} empty scans")
    fisst = run_fisst(scans)
    times = []
    ss_out = None
    for rep in range(REPS):
        t, ex, mean = run_stonesoup(scans, seed=rep + 1)
        times.append(t)
        ss_out = (ex, mean)
    rows = [
        ("Stone Soup 1.9.1 Bernoulli PF (5000 + MCMC)", float(np.median(times)), *metrics(truth, *ss_out)),
        ("fisst particle Bernoulli filter (5000 + MCMC)", fisst["pf"]["secondsPerStep"],
         *metrics(truth, fisst["pf"]["existence"], fisst["pf"]["mean"])),
        ("fisst GM Bernoulli filter", fisst["gm"]["secondsPerStep"],
         *metrics(truth, fisst["gm"]["existence"], fisst["gm"]["mean"])),
    ]
    print(f"{'filter':48s} {'ms/step':>9s} {'mean|r-1{x}|':>13s} {'pos RMSE':>9s} {'mean r after death':>19s}")
    for name, t, e, rmse, after in rows:
        print(f"{name:48s} {1e3 * t:9.3f} {e:13.4f} {rmse:9.3f} {after:19.4f}")
    ss = rows[0][1]
    print(f"speed-up over Stone Soup: fisst PF {ss / rows[1][1]:.1f}x, fisst GM {ss / rows[2][1]:.1f}x")
    print("empty scan from r = 0.8, p_D = 0.9 (exact 0.2857): "
          f"Stone Soup {stonesoup_empty_scan():.4f}, fisst GM {fisst['empty']['gm']:.4f}, "
          f"fisst PF {fisst['empty']['pf']:.4f}")


if __name__ == "__main__":
    main()
