//! A scene's exact area coverage ([`render_area`]): the scene prepared for an exact model
//! (snapped or not, clipped to its window), its shapes measured by the area oracle.

use std::fmt;

use super::{prepare, Model, ModelError, Primitives, Shape};
use crate::area::{exact, planned, triangle_shape, AreaImage, AreaShape, Semantics};
use crate::convention::Target;

/// Why a scene's area coverage cannot be computed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AreaError {
    /// The model cannot prepare the scene.
    Model(ModelError),
    /// Area coverage is exact only: the model is not one of the exact models.
    NotExact(Model),
    /// The scene has lines, which have no area.
    Lines(usize),
}

impl fmt::Display for AreaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AreaError::Model(e) => write!(f, "{e}"),
            AreaError::NotExact(m) => write!(
                f,
                "area coverage is computed exactly: model {m} is not one of exact, exact-snapped, exact-plain, exact-snapped-plain"
            ),
            AreaError::Lines(n) => write!(
                f,
                "the scene has {n} line(s): lines have no area (area coverage takes triangles, polygons and clip-space triangles)"
            ),
        }
    }
}

impl std::error::Error for AreaError {}

/// The shapes whose area `model` measures in the scene: each triangle and polygon after
/// the model's snapping and the clip window, in id order.
///
/// # Errors
/// The model cannot prepare the scene, is not exact, or the scene has lines.
pub fn area_shapes(primitives: &Primitives, target: &Target, model: Model) -> Result<Vec<AreaShape>, AreaError> {
    if !primitives.lines.is_empty() {
        return Err(AreaError::Lines(primitives.lines.len()));
    }
    let prepared = prepare(primitives, target, model).map_err(AreaError::Model)?;
    let shapes = prepared.shapes().ok_or(AreaError::NotExact(model))?;
    Ok(shapes
        .iter()
        .filter_map(|s| match s {
            Shape::Triangle(t) => Some(triangle_shape(t)),
            Shape::Polygon(p) => Some(p.clone()),
            Shape::Bresenham { .. } | Shape::Diamond { .. } => None,
        })
        .collect())
}

/// The scene's exact area coverage under `semantics`: by the plain oracle
/// ([`crate::area::exact`]) under the plain models (`exact-plain`,
/// `exact-snapped-plain`), by the planned engine ([`crate::area::planned`], equal to it)
/// under the others (which computes true coverage with the plain oracle too).
///
/// ```
/// use rasterproof::area::Semantics;
/// use rasterproof::model::{render_area, Model};
/// use rasterproof::scene::parse_scene;
/// let scene = parse_scene(
///     r#"{"width": 2, "height": 2, "triangles": [{"v": [[0, 0], [2, 0], [0, 2]]}]}"#,
///     "doc.json",
/// )
/// .unwrap();
/// let image = render_area(&scene.primitives(), &scene.target().unwrap(), Model::Exact, Semantics::True).unwrap();
/// // The pixel at the right angle is whole; the two along the hypotenuse are halves.
/// let half = num_rational::BigRational::new(1.into(), 2.into());
/// assert_eq!(image.value(0, 0), num_rational::BigRational::from_integer(1.into()));
/// assert_eq!((image.value(1, 0), image.value(0, 1)), (half.clone(), half));
/// assert_eq!(image.pixels.len(), 3);
/// ```
///
/// # Errors
/// As [`area_shapes`].
pub fn render_area(
    primitives: &Primitives,
    target: &Target,
    model: Model,
    semantics: Semantics,
) -> Result<AreaImage, AreaError> {
    let mut pixels = Vec::new();
    render_area_rows(primitives, target, model, semantics, |y, row| {
        pixels.extend(row.into_iter().map(|(x, v)| (x, y, v)));
    })?;
    Ok(AreaImage {
        width: target.width,
        height: target.height,
        semantics,
        pixels,
    })
}

/// The scene's exact area coverage under `semantics`, row by row (as [`render_area`]
/// computes it): `emit(y, pixels)` for every row, top first, with its non-zero `(x,
/// value)` by column. Under the planned models and an accumulated semantics the memory
/// does not grow with the canvas ([`crate::area::planned::for_each_row`]).
///
/// # Errors
/// As [`area_shapes`].
pub fn render_area_rows(
    primitives: &Primitives,
    target: &Target,
    model: Model,
    semantics: Semantics,
    emit: impl FnMut(u32, Vec<(u32, num_rational::BigRational)>),
) -> Result<(), AreaError> {
    let shapes = area_shapes(primitives, target, model)?;
    let (w, h) = (target.width, target.height);
    if matches!(model, Model::ExactPlain | Model::ExactSnappedPlain) {
        exact::rasterize(&shapes, w, h, semantics).for_each_row(emit);
    } else {
        planned::for_each_row(&shapes, w, h, semantics, emit);
    }
    Ok(())
}
