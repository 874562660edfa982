//! The SMC multi-object filter of paper `004` (Ristic & Vo, Sec. 4 and 5.2): multi-object
//! particles (11), the multi-object likelihood (20) computed exactly without enumerating the
//! associations, and the update / resample / regularise cycle with the MAP cardinality (22).

pub mod filter;
pub mod likelihood;
pub mod particles;

pub use filter::{Regularisation, regularise, resample, reweight, systematic};
pub use likelihood::{
    LikelihoodWorkspace, MultiObjectLikelihood, brute_force_ln_likelihood, ln_likelihood,
};
pub use particles::{Area, MultiObjectParticles, SetEstimate, State};
