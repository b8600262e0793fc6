//! Fills: flood fill on a raster (Smith 1979), scanline polygon fill with an active edge
//! table (Foley, van Dam et al.), and polygon triangulation (Luebke's fan, spade's
//! constrained Delaunay triangulation) after an exact validation by a plane sweep (Shamos
//! and Hoey 1976).

pub mod flood;
pub mod polygon;
mod sweep;
pub mod triangulate;
