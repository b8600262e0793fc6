//! The values family's workloads ([`workloads`]): seeded random triangles and a jittered
//! mesh, each vertex with a `w` and three channels in thirds, tenths and 256ths, with the
//! exact model's covered pixels; each triangle placed at a canvas offset with its values
//! scaled ([`ValueTri::setup`]).

use std::ops::RangeInclusive;

use num_rational::BigRational;
use proptest::prelude::prop;

use crate::convention::{Preset, Target};
use crate::geom::{Point, Triangle};
use crate::interp::values::{Interpolation, ValueSetup, ValueTriangle};
use crate::model::{prepare, Model, Primitives};
use crate::trade::measure::{unpack, Pairs};
use crate::trade::report::Axis;
use crate::trade::workloads::{draw, draw_n, runner};
use crate::trade::{Config, Magnitude};

use super::{OFFSETS, SCALES};

/// The channels of every workload's vertices: thirds, tenths, 256ths.
const DENOMINATORS: [i64; 3] = [3, 10, 256];
/// The random triangles' reach from vertex 0, px.
const REACH: i64 = 24;
/// The mesh's quads, px a side.
const CELL: u32 = 8;
/// Positions are drawn on this grid (1/256 px).
const GRID: i64 = 256;

/// One triangle of a workload at the origin: exact vertices, `w` and values.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueTri {
    /// The window positions.
    pub points: [Point; 3],
    /// Each vertex's clip-space `w`.
    pub w: [BigRational; 3],
    /// Each vertex's three channels.
    pub values: [Vec<BigRational>; 3],
}

impl ValueTri {
    /// The triangle moved by `(offset, offset)` px, every value multiplied by `scale`, both
    /// exactly.
    pub fn setup(&self, offset: u64, scale: u64) -> ValueSetup {
        let (m, s) = (
            BigRational::from_integer(offset.into()),
            BigRational::from_integer(scale.into()),
        );
        let p = self.points.each_ref().map(|p| Point::new(&p.x + &m, &p.y + &m));
        let values = self.values.each_ref().map(|v| v.iter().map(|v| v * &s).collect());
        ValueSetup::Triangle(Box::new(ValueTriangle::window(
            [&p[0], &p[1], &p[2]],
            [&self.w[0], &self.w[1], &self.w[2]],
            values,
        )))
    }
}

/// A workload of the values family at the origin.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueWorkload {
    /// Its name.
    pub name: String,
    /// How it is built.
    pub description: String,
    /// How its values are interpolated.
    pub interpolation: Interpolation,
    /// Its triangles (each covering a pixel at least).
    pub triangles: Vec<ValueTri>,
    /// Per triangle, the pixels it covers at the origin, row by row.
    pub pixels: Vec<Vec<(u32, u32)>>,
    /// The canvas side, px.
    pub side: u32,
    /// What its magnitudes measure.
    pub axis: Axis,
}

impl ValueWorkload {
    /// The magnitudes it is measured at: [`OFFSETS`] or [`SCALES`].
    pub fn magnitudes(&self) -> Vec<Magnitude> {
        let list: &[u64] = match self.axis {
            Axis::Offset => &OFFSETS,
            Axis::AttributeScale => &SCALES,
        };
        list.iter().map(|&m| Magnitude::new(m).expect("at most 2^32")).collect()
    }

    /// The offset and the scale of magnitude `m` on its axis.
    pub fn at(&self, m: Magnitude) -> (u64, u64) {
        match self.axis {
            Axis::Offset => (m.px(), 1),
            Axis::AttributeScale => (0, m.px()),
        }
    }

    /// Its covered (pixel, triangle) pairs.
    pub fn covered(&self) -> u64 {
        self.pixels.iter().map(|p| p.len() as u64).sum()
    }
}

/// One vertex's `w` and channels, drawn: `w = k/4` and `n/3`, `n/10`, `n/256` (`n >= 1`).
fn vertex_data((k, (a, b, c)): (i64, (i64, i64, i64))) -> (BigRational, Vec<BigRational>) {
    (
        BigRational::new(k.into(), 4.into()),
        [a, b, c]
            .iter()
            .zip(DENOMINATORS)
            .map(|(&n, d)| BigRational::new(n.into(), d.into()))
            .collect(),
    )
}

/// The strategy of one vertex's `k` and numerators (`DENOMINATORS`).
type VertexStrategy = (
    RangeInclusive<i64>,
    (RangeInclusive<i64>, RangeInclusive<i64>, RangeInclusive<i64>),
);

fn vertex_strategy() -> VertexStrategy {
    let [a, b, c] = DENOMINATORS;
    (1..=32, (1..=a, 1..=b, 1..=c))
}

/// `n` random triangles on a `side` px canvas (module docs).
fn random_triangles(config: &Config, n: usize, side: u32) -> Vec<ValueTri> {
    let span = i64::from(side) * GRID;
    let reach = REACH * GRID;
    let strategy = (
        (0..span, 0..span),
        prop::array::uniform4(-reach..=reach),
        prop::array::uniform3(vertex_strategy()),
    );
    draw_n(&mut runner(config.seed, "value triangles"), &strategy, n)
        .into_iter()
        .map(|((x, y), d, v)| {
            let at = |dx: i64, dy: i64| Point::from_fractions(x + dx, GRID, y + dy, GRID);
            let [(w0, f0), (w1, f1), (w2, f2)] = v.map(vertex_data);
            ValueTri {
                points: [at(0, 0), at(d[0], d[1]), at(d[2], d[3])],
                w: [w0, w1, w2],
                values: [f0, f1, f2],
            }
        })
        .collect()
}

/// A grid of `CELL` px quads over the canvas, inner vertices jittered (module docs).
fn mesh(config: &Config, side: u32) -> Vec<ValueTri> {
    let mut rng = runner(config.seed, "value mesh");
    let n = i64::from(side / CELL);
    let cell = i64::from(CELL) * GRID;
    let jitter = cell / 3;
    let mut vertices = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let inner = |k: i64| k > 0 && k < n;
            let (dx, dy, vertex) = draw(&mut rng, &(-jitter..=jitter, -jitter..=jitter, vertex_strategy()));
            let (dx, dy) = (if inner(i) { dx } else { 0 }, if inner(j) { dy } else { 0 });
            let (w, values) = vertex_data(vertex);
            vertices.push((
                Point::from_fractions(i * cell + dx, GRID, j * cell + dy, GRID),
                w,
                values,
            ));
        }
    }
    let at = |i: i64, j: i64| usize::try_from(j * (n + 1) + i).expect("a vertex");
    let mut out = Vec::new();
    for j in 0..n {
        for i in 0..n {
            for t in [
                [at(i, j), at(i + 1, j), at(i, j + 1)],
                [at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)],
            ] {
                let v = t.map(|k| &vertices[k]);
                out.push(ValueTri {
                    points: v.map(|v| v.0.clone()),
                    w: v.map(|v| v.1.clone()),
                    values: v.map(|v| v.2.clone()),
                });
            }
        }
    }
    out
}

/// Each triangle's covered pixels under the exact model, row by row; the triangles that
/// cover none are left out.
fn with_pixels(triangles: Vec<ValueTri>, side: u32) -> (Vec<ValueTri>, Vec<Vec<(u32, u32)>>) {
    let target = Target::new(side, side, Preset::Vulkan.convention()).expect("the trade's canvas");
    let geometry: Vec<Triangle> = triangles
        .iter()
        .map(|t| Triangle::new(t.points[0].clone(), t.points[1].clone(), t.points[2].clone()))
        .collect();
    let prepared = prepare(&Primitives::from_triangles(&geometry), &target, Model::Exact)
        .expect("the exact model takes every triangle");
    let mut pairs = Pairs::default();
    prepared.render(&target, &mut pairs);
    let mut pixels = vec![Vec::new(); triangles.len()];
    for &k in &pairs.sorted().0 {
        let (x, y, id) = unpack(k);
        pixels[usize::try_from(id).expect("an id")].push((x, y));
    }
    triangles.into_iter().zip(pixels).filter(|(_, p)| !p.is_empty()).unzip()
}

/// The family's workloads at the origin, on the canvas offset axis: smooth triangles,
/// noperspective triangles (the same triangles) and the smooth mesh. The run measures the
/// two triangle workloads again on the attribute scale axis.
pub fn workloads(config: &Config) -> Vec<ValueWorkload> {
    let sizes = config.sizes();
    let side = sizes.canvas;
    let count = 40 * sizes.count;
    let (triangles, pixels) = with_pixels(random_triangles(config, count, side), side);
    let drawn = |what: &str| {
        format!(
            "{} random triangles covering a pixel (of {count} drawn: vertex 0 on the 1/256 px grid of the {side} px \
             canvas, the others within {REACH} px of it), each vertex a w of k/4 (k in 1..=32) and three channels \
             in (0, 1]: n/3, n/10, n/256 (n from 1); {what}.",
            triangles.len()
        )
    };
    let both = |interpolation: Interpolation, name: &str| ValueWorkload {
        name: name.into(),
        description: drawn(&format!("interpolated {interpolation}")),
        interpolation,
        triangles: triangles.clone(),
        pixels: pixels.clone(),
        side,
        axis: Axis::Offset,
    };
    let (mesh, mesh_pixels) = with_pixels(mesh(config, side), side);
    vec![
        both(Interpolation::Smooth, "smooth triangles"),
        both(Interpolation::NoPerspective, "noperspective triangles"),
        ValueWorkload {
            name: "values mesh".into(),
            description: format!(
                "A mesh of {} triangles over the {side} px canvas: a grid of {CELL} px quads, inner vertices \
                 jittered by up to a third of a cell on the 1/256 px grid, each vertex a w of k/4 and three \
                 channels n/3, n/10, n/256 (n from 1); interpolated smooth.",
                mesh.len()
            ),
            interpolation: Interpolation::Smooth,
            triangles: mesh,
            pixels: mesh_pixels,
            side,
            axis: Axis::Offset,
        },
    ]
}
