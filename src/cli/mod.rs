//! Subcommands of the binary.

pub mod check;
pub mod flood;
pub mod render;
