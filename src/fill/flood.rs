//! Flood fill on a raster (seed 002). Work in progress.
