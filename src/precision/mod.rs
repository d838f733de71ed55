//! Precision testing tools: error metrics and adversarial test inputs, public so that
//! downstream suites measure their own shaders the way this crate measures its own.

pub mod inputs;
pub mod metrics;
