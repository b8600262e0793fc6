//! Fills: flood fill on a raster (Smith 1979), scanline polygon fill with an active edge
//! table (Foley, van Dam et al.), and polygon triangulation (Luebke's fan, spade's
//! constrained Delaunay triangulation).

pub mod flood;
pub mod polygon;
pub mod triangulate;
