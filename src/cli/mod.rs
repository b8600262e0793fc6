//! Subcommands of the binary.

pub mod check;
pub mod clip;
pub mod flood;
pub mod render;
