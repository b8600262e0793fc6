//! Subcommands of the binary.

pub mod check;
pub mod render;
