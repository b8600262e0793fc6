//! Triangle rasterizers, one file per numeric model, each with the same shape:
//! `rasterize(triangle, id, &Target, &mut sink)`, the triangle in the model's own input
//! form (exact [`crate::geom::Triangle`], fixed [`crate::geom::FixedTriangle`], glam
//! vectors for float); the model module converts a scene's exact triangles for each, and
//! [`crate::raster`] says where their samples sit. `blocks.rs` holds the block kernel
//! that `fixed` and `planned` share.

mod blocks;
pub mod conservative;
pub mod exact;
pub mod fixed;
pub mod float;
pub mod planned;
pub mod scanline;
