//! Another renderer as a process: run once per scene with a timeout, in a process group of
//! its own ([`program::Program`]), or kept alive across scenes ([`stay_alive::StayAlive`]),
//! both a [`program::Renderer`]; and the renderer's side of both protocols, for an adapter
//! written in Rust ([`adapter`]).

pub mod adapter;
pub mod program;
pub mod stay_alive;

pub use program::{FailureKind, Program, RenderFailure, Renderer, RendererRuns};
pub use stay_alive::StayAlive;
