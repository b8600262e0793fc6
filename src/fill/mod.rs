//! Fills: flood fill on a raster (seed 002), scanline polygon fill with an active edge
//! table (seed 002), and polygon triangulation (seed 004's fan, spade's constrained
//! Delaunay triangulation).

pub mod flood;
pub mod polygon;
pub mod triangulate;
