//! Scene files (JSON): the canvas, the convention and the primitives, every coordinate
//! read exactly as written. See [`parse::parse_scene`] for the format and its errors.

mod file;
pub mod parse;

use std::fmt;
use std::fmt::Write as _;

use num_rational::BigRational;

use crate::clip::arithmetic::{ClipArithmetic, Clipped, Clipper};
use crate::clip::homogeneous::{ClipVertex, DepthRange, NdcY, Viewport};
use crate::clip::Window;
use crate::convention::{Convention, PixelCentre, Preset, Rounding, Target, TieRule};
use crate::geom::Rgb;
use crate::geom::{CompactTriangle, Point, Polygon, Triangle};
use crate::interp::values::{ValueSegment, ValueSetup, ValueTriangle, Varyings};
use crate::line::{Line, LineRule};
use crate::model::Primitives;
use crate::num::compact::Compact;
use crate::num::exact::{exact_text, json_pair};
use crate::pattern::SamplePattern;

pub use file::read_scene_file;
pub use parse::{parse_scene, parse_scene_with, ParseOptions};

/// Choices a scene makes on top of its preset.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Overrides {
    /// `subpixel_bits`.
    pub subpixel_bits: Option<u32>,
    /// `rounding`.
    pub rounding: Option<Rounding>,
    /// `tie_rule`.
    pub tie_rule: Option<TieRule>,
    /// `pixel_centre`.
    pub pixel_centre: Option<PixelCentre>,
}

impl Overrides {
    /// `preset`'s convention with these overrides applied.
    pub fn apply(&self, preset: Preset) -> Convention {
        let base = preset.convention();
        Convention {
            preset,
            subpixel_bits: self.subpixel_bits.unwrap_or(base.subpixel_bits),
            rounding: self.rounding.unwrap_or(base.rounding),
            tie_rule: self.tie_rule.unwrap_or(base.tie_rule),
            pixel_centre: self.pixel_centre.unwrap_or(base.pixel_centre),
        }
    }
}

/// A triangle of a scene, with optional vertex colours and values (the default: every
/// vertex at the origin, no colours, no values).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SceneTriangle {
    /// The exact triangle, in compact form ([`CompactTriangle::to_triangle`] reads it).
    pub triangle: CompactTriangle,
    /// `colors`: one RGB per vertex.
    pub colours: Option<[Rgb; 3]>,
    /// `varyings` and `w`: the values of the scene's varyings at each vertex (present
    /// exactly when the scene declares varyings).
    pub values: Option<Box<VertexValues>>,
}

/// A window-space triangle's per-vertex values: the scene's varyings, and optionally each
/// vertex's clip-space `w` for perspective correction.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VertexValues {
    /// `w`: each vertex's clip-space w, `> 0`; `None` is 1 at every vertex (then `smooth`
    /// and `noperspective` agree).
    pub w: Option<[BigRational; 3]>,
    /// `varyings`: per vertex, every declared varying's channels in declaration order.
    pub values: [Vec<BigRational>; 3],
}

/// A parsed, validated scene.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    /// Canvas width, `1..=16384`.
    pub width: u32,
    /// Canvas height, `1..=16384`.
    pub height: u32,
    /// `preset` (default `d3d11`).
    pub preset: Preset,
    /// The scene's own overrides of the preset.
    pub overrides: Overrides,
    /// `triangles`, ids 0.. in file order.
    pub triangles: Vec<SceneTriangle>,
    /// `lines`, ids after the triangles, in file order.
    pub lines: Vec<Line>,
    /// Each line's `varyings`: the values at `from` and at `to` (one entry per line when the
    /// scene declares varyings, none otherwise).
    pub line_values: Vec<[Vec<BigRational>; 2]>,
    /// `polygons`, ids after the triangles and the lines, in file order.
    pub polygons: Vec<Polygon>,
    /// `clip_space_triangles`: clip-space `(x, y, z, w)` vertices, clipped against the
    /// view volume, divided and mapped through the viewport; ids after the polygons.
    pub clip_space_triangles: Vec<[ClipVertex; 3]>,
    /// `viewport`, when the file gives one (see [`Scene::viewport`] for the default).
    pub viewport: Option<Viewport>,
    /// `clip`: the window every primitive is clipped against before rasterization.
    pub clip: Option<Window>,
    /// `samples`: the pixel's sample pattern (multisampling); `None` is the convention's
    /// one sample per pixel.
    pub samples: Option<SamplePattern>,
    /// `varyings` and `provoking_vertex`: the attributes every triangle and clip-space
    /// triangle carries per vertex (clip-space ones in [`ClipVertex::attrs`]); none
    /// declared by default.
    pub varyings: Varyings,
}

impl Scene {
    /// A scene with the default preset and no overrides.
    pub fn new(width: u32, height: u32, triangles: Vec<Triangle>) -> Scene {
        Scene {
            width,
            height,
            preset: Preset::D3d11,
            overrides: Overrides::default(),
            triangles: triangles
                .into_iter()
                .map(|triangle| SceneTriangle {
                    triangle: triangle.into(),
                    colours: None,
                    values: None,
                })
                .collect(),
            lines: Vec::new(),
            line_values: Vec::new(),
            polygons: Vec::new(),
            clip_space_triangles: Vec::new(),
            viewport: None,
            clip: None,
            samples: None,
            varyings: Varyings::default(),
        }
    }

    /// Each primitive's interpolation setup ([`crate::interp::values`]), by id (triangles,
    /// lines, polygons, clip-space triangles): a triangle's window vertices with its `w` (1
    /// where it gives none) and values; a line's ends and values; a clip-space triangle's
    /// homogeneous window vertices under [`Scene::viewport`] with its values (a Bresenham
    /// line's ends are the sample points of its end pixels, a diamond-exit line's are its
    /// points); `None` for a polygon, and for every primitive when the scene declares no
    /// varyings.
    pub fn value_setups(&self) -> Vec<Option<ValueSetup>> {
        let mut out = Vec::with_capacity(
            self.triangles.len() + self.lines.len() + self.polygons.len() + self.clip_space_triangles.len(),
        );
        let one = BigRational::from_integer(1.into());
        for t in &self.triangles {
            out.push(t.values.as_ref().map(|v| {
                let tri = t.triangle.to_triangle();
                let w = v.w.as_ref().map_or([&one, &one, &one], |w| [&w[0], &w[1], &w[2]]);
                ValueSetup::Triangle(Box::new(ValueTriangle::window(
                    [&tri.v[0], &tri.v[1], &tri.v[2]],
                    w,
                    v.values.clone(),
                )))
            }));
        }
        // A Bresenham line's ends name pixels: they are the pixels' sample points.
        let centre = self.convention().pixel_centre.offset();
        for (k, l) in self.lines.iter().enumerate() {
            let end = |p: &Point| match l.rule {
                LineRule::Bresenham(_) => Point::new(&p.x + &centre, &p.y + &centre),
                LineRule::Diamond => p.clone(),
            };
            out.push(self.line_values.get(k).map(|values| {
                ValueSetup::Segment(Box::new(ValueSegment {
                    ends: [end(&l.from), end(&l.to)],
                    values: values.clone(),
                }))
            }));
        }
        out.resize(out.len() + self.polygons.len(), None);
        let viewport = self.viewport();
        for t in &self.clip_space_triangles {
            out.push((!self.varyings.list.is_empty()).then(|| {
                ValueSetup::Triangle(Box::new(ValueTriangle {
                    h: [0, 1, 2].map(|i| viewport.homogeneous(&t[i].pos)),
                    values: [0, 1, 2].map(|i| t[i].attrs.clone()),
                }))
            }));
        }
        out
    }

    /// The viewport: the file's, or the whole canvas with the preset's conventions (NDC y
    /// down for `vulkan`, up for the others; depth `-w <= z <= w` for `gl`, `0 <= z <= w`
    /// for the others).
    pub fn viewport(&self) -> Viewport {
        self.viewport.clone().unwrap_or_else(|| {
            let int = |v: u32| BigRational::from_integer(v.into());
            Viewport {
                x: int(0),
                y: int(0),
                width: int(self.width),
                height: int(self.height),
                y_axis: preset_ndc(self.preset).0,
                depth: preset_ndc(self.preset).1,
            }
        })
    }

    /// The convention: the preset with the scene's overrides.
    pub fn convention(&self) -> Convention {
        self.overrides.apply(self.preset)
    }

    /// The canvas and convention. Parsing validated both, so this cannot fail for a parsed
    /// scene; a hand-built one (or one whose overrides were changed) with a side outside
    /// `1..=MAX_CANVAS` or subpixel bits outside `1..=MAX_SUBPIXEL_BITS` gets an error
    /// naming the field and its value.
    ///
    /// # Errors
    /// The canvas or the subpixel bits are out of range.
    pub fn target(&self) -> Result<Target, SceneError> {
        let convention = self.convention();
        Target::new(self.width, self.height, convention).ok_or_else(|| {
            let max = crate::convention::MAX_CANVAS;
            let (field, message) = if !(1..=max).contains(&self.width) {
                ("width", format!("{} is outside 1..={max}", self.width))
            } else if !(1..=max).contains(&self.height) {
                ("height", format!("{} is outside 1..={max}", self.height))
            } else {
                (
                    "subpixel_bits",
                    format!(
                        "{} is outside 1..={}",
                        convention.subpixel_bits,
                        crate::num::MAX_SUBPIXEL_BITS
                    ),
                )
            };
            SceneError {
                source: "<scene>".into(),
                field: field.into(),
                message,
            }
        })
    }

    /// The exact triangles, in id order.
    pub fn triangles(&self) -> Vec<Triangle> {
        self.triangles.iter().map(|t| t.triangle.to_triangle()).collect()
    }

    /// What the scene draws, for [`crate::model::render`] and [`crate::model::prepare`]:
    /// its triangles, lines, polygons, clip-space triangles, the viewport
    /// ([`Scene::viewport`]) and the clip window.
    pub fn primitives(&self) -> Primitives {
        self.primitives_parallel(1)
    }

    /// [`Scene::primitives`], the triangles copied on up to `jobs` threads.
    pub fn primitives_parallel(&self, jobs: usize) -> Primitives {
        Primitives {
            triangles: crate::chunks::map(&self.triangles, jobs, |_, t| t.triangle.clone()),
            lines: self.lines.clone(),
            polygons: self.polygons.clone(),
            clip_space_triangles: self.clip_space_triangles.clone(),
            viewport: Some(self.viewport()),
            clip: self.clip.clone(),
        }
    }

    /// Every primitive clipped against the scene's window in `arithmetic` (nothing is
    /// clipped without one) by one [`Clipper`], in input order: triangles and polygon
    /// contours by [`Clipper::contour`], lines by [`Clipper::segment`], clip-space
    /// triangles through [`Scene::viewport`] by [`Clipper::clip_space`] (`divide_first`:
    /// divided first and clipped in 2D, exact only). What `rasterproof clip` prints.
    ///
    /// # Errors
    /// The first primitive that cannot be clipped in `arithmetic` (a coordinate beyond the
    /// float type, a float result that is not finite, `divide_first` outside exact
    /// arithmetic or with `w <= 0`) or a window line beyond the float type: one sentence
    /// naming the field (`triangles[2]`) or the window edge.
    ///
    /// ```
    /// use rasterproof::clip::arithmetic::ClipArithmetic;
    /// use rasterproof::scene::parse_scene;
    /// let scene = parse_scene(
    ///     r#"{"width": 8, "height": 8, "triangles": [{"v": [[0, 0], [8, 0], [0, 8]]}],
    ///         "clip": {"rect": [0, 0, 4, 4]}}"#,
    ///     "example.json",
    /// )
    /// .unwrap();
    /// let clipped = scene.clipped(ClipArithmetic::Exact, false).unwrap();
    /// assert_eq!(clipped.to_json(), r#"{"triangles":[[["0","4"],["0","0"],["4","0"],["4","4"]]],"lines":[],"polygons":[],"clip_space_triangles":[]}"#);
    /// assert_eq!(clipped.to_text("example.json"), "example.json: exact clipping: 1/1 triangles, 0/0 lines, 0/0 polygons, 0/0 clip-space triangles keep something");
    /// ```
    pub fn clipped(&self, arithmetic: ClipArithmetic, divide_first: bool) -> Result<Clipped, String> {
        let clipper = Clipper::new(arithmetic, self.clip.as_ref())?;
        let mut triangles = Vec::new();
        for (k, t) in self.triangles.iter().enumerate() {
            triangles.push(clipper.contour(&t.triangle.to_triangle().v, &format!("triangles[{k}]"))?);
        }
        let mut lines = Vec::new();
        for (k, l) in self.lines.iter().enumerate() {
            lines.push(clipper.segment(&l.from, &l.to, &format!("lines[{k}]"))?);
        }
        let mut polygons = Vec::new();
        for (k, p) in self.polygons.iter().enumerate() {
            let what = format!("polygons[{k}]");
            let outline = clipper.contour(&p.outline, &what)?;
            if outline.is_empty() {
                polygons.push(Vec::new());
                continue;
            }
            let mut contours = vec![outline];
            for h in &p.holes {
                contours.push(clipper.contour(h, &what)?);
            }
            polygons.push(contours);
        }
        let mut clip_space_triangles = Vec::new();
        let viewport = self.viewport();
        for (k, t) in self.clip_space_triangles.iter().enumerate() {
            let what = format!("clip_space_triangles[{k}]");
            clip_space_triangles.push(clipper.clip_space(t, &viewport, divide_first, &what)?);
        }
        Ok(Clipped {
            arithmetic,
            triangles,
            lines,
            polygons,
            clip_space_triangles,
        })
    }

    /// The vertex colours, in id order.
    pub fn colours(&self) -> Vec<Option<[Rgb; 3]>> {
        self.triangles.iter().map(|t| t.colours).collect()
    }

    /// Every window-space coordinate, `x` then `y` of each vertex: the triangles', the
    /// lines' ends, the polygons' outlines then holes (not the clip-space triangles',
    /// which are in clip space).
    pub fn coordinates(&self) -> Vec<BigRational> {
        let triangles = self
            .triangles
            .iter()
            .flat_map(|t| t.triangle.v.iter().flatten().map(Compact::to_big));
        let points = self.lines.iter().flat_map(|l| [&l.from, &l.to]).chain(
            self.polygons
                .iter()
                .flat_map(|p| p.outline.iter().chain(p.holes.iter().flatten())),
        );
        triangles
            .chain(points.flat_map(|v| [v.x.clone(), v.y.clone()]))
            .collect()
    }

    /// Replaces each coordinate of [`Scene::coordinates`] by `f(k, value)`, `k` its
    /// position in that list.
    pub fn map_coordinates(&mut self, mut f: impl FnMut(usize, &BigRational) -> BigRational) {
        let mut k = 0;
        let mut next = |x: &BigRational| {
            k += 1;
            f(k - 1, x)
        };
        for t in &mut self.triangles {
            for v in &mut t.triangle.v {
                for c in v {
                    *c = Compact::from_big(next(&c.to_big()));
                }
            }
        }
        let points = self.lines.iter_mut().flat_map(|l| [&mut l.from, &mut l.to]).chain(
            self.polygons
                .iter_mut()
                .flat_map(|p| p.outline.iter_mut().chain(p.holes.iter_mut().flatten())),
        );
        for v in points {
            v.x = next(&v.x);
            v.y = next(&v.y);
        }
    }

    /// The scene as a scene file, every coordinate an exact string (`"7/3"`), so that
    /// parsing it again gives the same scene.
    pub fn to_json(&self) -> String {
        let mut s = self.header_json();
        let varyings = &self.varyings;
        if !varyings.list.is_empty() {
            let list: Vec<String> = varyings
                .list
                .iter()
                .map(|v| {
                    format!(
                        "{{\"name\": {}, \"channels\": {}, \"interpolation\": \"{}\", \"sampling\": \"{}\"}}",
                        serde_json::Value::from(v.name.as_str()),
                        v.channels,
                        v.interpolation.name(),
                        v.sampling.name()
                    )
                })
                .collect();
            let _ = write!(
                s,
                "  \"varyings\": [{}],\n  \"provoking_vertex\": \"{}\",\n",
                list.join(", "),
                varyings.provoking.name()
            );
        }
        let _ = write!(
            s,
            "  \"triangles\": {}",
            json_lines(self.triangles.iter().map(|t| triangle_json(t, varyings)))
        );
        if !self.lines.is_empty() {
            let items = (self.lines.iter().enumerate()).map(|(k, l)| line_json(l, self.line_values.get(k), varyings));
            let _ = write!(s, ",\n  \"lines\": {}", json_lines(items));
        }
        if !self.polygons.is_empty() {
            let _ = write!(
                s,
                ",\n  \"polygons\": {}",
                json_lines(self.polygons.iter().map(polygon_json))
            );
        }
        if !self.clip_space_triangles.is_empty() {
            let items = self.clip_space_triangles.iter().map(|t| clip_space_json(t, varyings));
            let _ = write!(s, ",\n  \"clip_space_triangles\": {}", json_lines(items));
        }
        if let Some(vp) = &self.viewport {
            let _ = write!(
                s,
                ",\n  \"viewport\": {{\"x\": \"{}\", \"y\": \"{}\", \"width\": \"{}\", \"height\": \"{}\", \"ndc_y\": \"{}\", \"depth\": \"{}\"}}",
                exact_text(&vp.x),
                exact_text(&vp.y),
                exact_text(&vp.width),
                exact_text(&vp.height),
                if vp.y_axis == NdcY::Down { "down" } else { "up" },
                if vp.depth == DepthRange::ZeroToOne { "zero-to-one" } else { "minus-one-to-one" }
            );
        }
        if let Some(clip) = &self.clip {
            let _ = write!(s, ",\n  \"clip\": {}", window_json(clip));
        }
        if let Some(pattern) = &self.samples {
            let _ = write!(s, ",\n  \"samples\": {}", pattern.to_json());
        }
        s.push_str("\n}\n");
        s
    }

    /// The scene file's first lines: the canvas, the preset and its overrides.
    fn header_json(&self) -> String {
        let mut s = format!(
            "{{\n  \"width\": {},\n  \"height\": {},\n  \"preset\": \"{}\",\n",
            self.width,
            self.height,
            self.preset.name()
        );
        let o = &self.overrides;
        if let Some(b) = o.subpixel_bits {
            let _ = writeln!(s, "  \"subpixel_bits\": {b},");
        }
        if let Some(r) = o.rounding {
            let _ = writeln!(s, "  \"rounding\": \"{}\",", r.name());
        }
        if let Some(t) = o.tie_rule {
            let _ = writeln!(s, "  \"tie_rule\": \"{}\",", t.name());
        }
        if let Some(c) = o.pixel_centre {
            let _ = writeln!(s, "  \"pixel_centre\": {},", c.name());
        }
        s
    }
}

/// `items` as a scene file's array, one item a line.
fn json_lines(items: impl Iterator<Item = String>) -> String {
    let mut s = String::from("[");
    for (k, item) in items.enumerate() {
        s.push_str(if k == 0 { "\n    " } else { ",\n    " });
        s.push_str(&item);
    }
    s.push_str("\n  ]");
    s
}

/// A triangle of a scene file: its vertices, and its colours and values where it has them.
fn triangle_json(t: &SceneTriangle, varyings: &Varyings) -> String {
    let v: Vec<String> = t.triangle.to_triangle().v.iter().map(pt).collect();
    let mut s = format!("{{\"v\": [{}]", v.join(", "));
    if let Some(c) = t.colours {
        let c: Vec<String> = c.iter().map(|c| format!("[{}, {}, {}]", c[0], c[1], c[2])).collect();
        let _ = write!(s, ", \"colors\": [{}]", c.join(", "));
    }
    if let Some(values) = &t.values {
        if let Some(w) = &values.w {
            let w: Vec<String> = w.iter().map(|w| format!("\"{}\"", exact_text(w))).collect();
            let _ = write!(s, ", \"w\": [{}]", w.join(", "));
        }
        let _ = write!(s, ", \"varyings\": {}", values_json(&values.values, varyings));
    }
    s.push('}');
    s
}

/// A primitive's `varyings` object: each varying's channels at each vertex.
fn values_json(values: &[Vec<BigRational>], varyings: &Varyings) -> String {
    let fields: Vec<String> = varyings
        .ranges()
        .map(|(v, range)| {
            let vertices: Vec<String> = values
                .iter()
                .map(|vertex| {
                    let channels: Vec<String> = vertex[range.clone()]
                        .iter()
                        .map(|c| format!("\"{}\"", exact_text(c)))
                        .collect();
                    format!("[{}]", channels.join(", "))
                })
                .collect();
            format!(
                "{}: [{}]",
                serde_json::Value::from(v.name.as_str()),
                vertices.join(", ")
            )
        })
        .collect();
    format!("{{{}}}", fields.join(", "))
}

/// A line of a scene file: its ends, its rule, and its ends' values where it has them.
fn line_json(l: &Line, values: Option<&[Vec<BigRational>; 2]>, varyings: &Varyings) -> String {
    let rule = match l.rule {
        LineRule::Bresenham(tie) => format!("\"rule\": \"bresenham\", \"tie\": \"{}\"", tie.name()),
        LineRule::Diamond => "\"rule\": \"diamond\"".to_string(),
    };
    let values = values.map_or(String::new(), |v| {
        format!(", \"varyings\": {}", values_json(v, varyings))
    });
    format!("{{\"from\": {}, \"to\": {}, {rule}{values}}}", pt(&l.from), pt(&l.to))
}

/// A contour of a scene file: its points.
fn contour_json(c: &[Point]) -> String {
    format!("[{}]", c.iter().map(pt).collect::<Vec<_>>().join(", "))
}

/// A polygon of a scene file: its outline, its holes where it has them, its fill rule.
fn polygon_json(p: &Polygon) -> String {
    let mut s = format!("{{\"v\": {}", contour_json(&p.outline));
    if !p.holes.is_empty() {
        let holes: Vec<String> = p.holes.iter().map(|h| contour_json(h)).collect();
        let _ = write!(s, ", \"holes\": [{}]", holes.join(", "));
    }
    let _ = write!(s, ", \"fill_rule\": \"{}\"}}", p.fill_rule.name());
    s
}

/// A clip-space triangle of a scene file: each vertex's four exact coordinates, and its
/// values where the scene declares varyings.
fn clip_space_json(t: &[ClipVertex; 3], varyings: &Varyings) -> String {
    let v: Vec<String> = t
        .iter()
        .map(|v| {
            format!(
                "[{}]",
                v.pos
                    .iter()
                    .map(|c| format!("\"{}\"", exact_text(c)))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect();
    if varyings.list.is_empty() {
        return format!("{{\"v\": [{}]}}", v.join(", "));
    }
    let values = [0, 1, 2].map(|i| t[i].attrs.clone());
    format!(
        "{{\"v\": [{}], \"varyings\": {}}}",
        v.join(", "),
        values_json(&values, varyings)
    )
}

/// A clip window of a scene file: a rectangle's four sides or a convex window's points.
fn window_json(w: &Window) -> String {
    match w {
        Window::Rect(r) => format!(
            "{{\"rect\": [\"{}\", \"{}\", \"{}\", \"{}\"]}}",
            exact_text(&r.xmin),
            exact_text(&r.ymin),
            exact_text(&r.xmax),
            exact_text(&r.ymax)
        ),
        Window::Convex(pts) => {
            let pts: Vec<String> = pts.iter().map(pt).collect();
            format!("{{\"convex\": [{}]}}", pts.join(", "))
        }
    }
}

/// A preset's clip-space conventions: NDC y down for `vulkan`, up for the others; depth
/// `-w <= z <= w` for `gl`, `0 <= z <= w` for the others.
pub fn preset_ndc(preset: Preset) -> (NdcY, DepthRange) {
    (
        if preset == Preset::Vulkan { NdcY::Down } else { NdcY::Up },
        if preset == Preset::Gl {
            DepthRange::MinusOneToOne
        } else {
            DepthRange::ZeroToOne
        },
    )
}

/// A point as scene text: `["3", "-7/2"]`.
fn pt(p: &Point) -> String {
    json_pair(&p.x, &p.y)
}

/// Bad scene input: which file, which field, what value, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SceneError {
    /// The file (or `<stdin>`, `<bytes>`).
    pub source: String,
    /// The field path, e.g. `triangles[2].v[1][0]`; empty for whole-file errors.
    pub field: String,
    /// What is wrong, with the offending value.
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}: {}", self.source, self.message)
        } else {
            write!(f, "{}: {}: {}", self.source, self.field, self.message)
        }
    }
}

impl std::error::Error for SceneError {}
