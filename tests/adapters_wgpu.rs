//! The wgpu adapter (adapters/wgpu/): filled in by its author.
