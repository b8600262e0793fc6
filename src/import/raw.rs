//! Raw little-endian f32 position buffers (a buffer saved from a capture's buffer viewer,
//! RenderDoc's "Export to Bytes", or one's own engine): `count` vertices of 2, 3 or 4
//! floats, the first at byte `offset`, each `stride` bytes after the last; with an
//! optional index buffer of u16 or u32 (a triangle list: indices in threes), or else the
//! vertices themselves in threes. Every float is read exactly ([`exact_f32`]).
//!
//! - **Window space**: `x, y` are pixels (x right, y down); further components are
//!   ignored. The scene's `triangles`.
//! - **Clip space**: `x, y, z, w`; 2 components mean `z = 0, w = 1`, 3 mean `w = 1`. The
//!   scene's `clip_space_triangles` with the viewport ([`super::scene_viewport`]).
//!
//! Both files are read once, front to back, through a buffer: only the vertices' floats
//! (16 bytes a vertex) and the indices are held, never the file; the lengths are checked
//! before anything is read.

use std::io::{self, BufReader, Read};

use num_rational::BigRational;

use super::{clip_triangles, counted, exact_f32, ImportError, ImportTarget, Imported, MAX_VERTICES};
use crate::geom::{Point, Triangle};
use crate::scene::parse::MAX_TRIANGLES;

/// Where the vertices sit in the vertex buffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Floats per vertex: 2, 3 or 4.
    pub components: u32,
    /// Bytes from one vertex to the next, at least `4 * components`.
    pub stride: u64,
    /// The first vertex's byte offset.
    pub offset: u64,
    /// How many vertices; `None`: as many whole vertices as the file holds from `offset`.
    pub count: Option<u64>,
}

/// The size of one index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IndexType {
    /// 16-bit indices.
    U16,
    /// 32-bit indices.
    U32,
}

impl IndexType {
    /// Bytes per index.
    pub fn size(self) -> u64 {
        match self {
            IndexType::U16 => 2,
            IndexType::U32 => 4,
        }
    }

    /// `u16` or `u32`.
    pub fn name(self) -> &'static str {
        match self {
            IndexType::U16 => "u16",
            IndexType::U32 => "u32",
        }
    }

    /// Parses a name written by [`IndexType::name`].
    pub fn from_name(name: &str) -> Option<IndexType> {
        [IndexType::U16, IndexType::U32].into_iter().find(|t| t.name() == name)
    }
}

/// What the positions are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Space {
    /// Window-space pixels, `x, y`.
    Window,
    /// Clip space, `x, y, z, w`.
    Clip,
}

/// One input file: its name (for errors and the summary), its length in bytes and a
/// reader at its start.
pub struct RawFile<R> {
    /// The file's name as the user gave it.
    pub name: String,
    /// Its length, bytes.
    pub len: u64,
    /// Its bytes, from the start.
    pub reader: R,
}

/// The vertices read as f32, padded to four (`z = 0`, `w = 1`), with where each sits.
struct Vertices {
    floats: Vec<[f32; 4]>,
    layout: Layout,
}

impl Vertices {
    /// Vertex `k`'s exact coordinates, or the error naming the vertex, its component, its
    /// byte offset and value.
    fn exact(&self, k: usize, source: &str) -> Result<[BigRational; 4], ImportError> {
        let v = self.floats[k];
        let mut out: [BigRational; 4] = Default::default();
        for (c, slot) in out.iter_mut().enumerate() {
            *slot = exact_f32(v[c]).ok_or_else(|| {
                let at = self.layout.offset + k as u64 * self.layout.stride + 4 * c as u64;
                ImportError::new(
                    source,
                    format!(
                        "vertex {k}, {} (byte {at}): {} is not a finite number",
                        ["x", "y", "z", "w"][c],
                        v[c]
                    ),
                )
            })?;
        }
        Ok(out)
    }
}

/// Reads the vertex buffer `vertices` (with `index`, its index buffer and index type) into
/// a scene on `target`: window-space `triangles` or clip-space `clip_space_triangles`.
///
/// ```
/// use rasterproof::convention::Preset;
/// use rasterproof::import::raw::{import_raw, Layout, RawFile, Space};
/// use rasterproof::import::ImportTarget;
/// // One window-space triangle, x y pairs: (0, 0), (4, 0), (0, 0.1).
/// let bytes: Vec<u8> = [0.0f32, 0.0, 4.0, 0.0, 0.0, 0.1].iter().flat_map(|f| f.to_le_bytes()).collect();
/// let file = RawFile { name: "pos.bin".into(), len: bytes.len() as u64, reader: &bytes[..] };
/// let layout = Layout { components: 2, stride: 8, offset: 0, count: None };
/// let target = ImportTarget { width: 4, height: 4, preset: Preset::D3d11, viewport: None };
/// let imported = import_raw(file, &layout, None::<(RawFile<&[u8]>, _)>, Space::Window, &target).unwrap();
/// // 0.1f32 is exactly 13421773 / 2^27.
/// assert_eq!(imported.scene.triangles()[0].v[2].y.to_string(), "13421773/134217728");
/// ```
///
/// # Errors
/// A bad layout (components not 2, 3 or 4; a stride below `4 * components`), a file too
/// short for the layout (`truncated: ... need N bytes, the file has M`), a vertex count
/// (no index buffer) or index count that is not a multiple of 3, an index buffer whose
/// length is not a multiple of the index size, an index out of range, a coordinate that
/// is not a finite number, more than [`MAX_TRIANGLES`] triangles or [`MAX_VERTICES`]
/// vertices, a read that fails, and a bad canvas or viewport.
pub fn import_raw<R: Read, S: Read>(
    vertices: RawFile<R>,
    layout: &Layout,
    index: Option<(RawFile<S>, IndexType)>,
    space: Space,
    target: &ImportTarget,
) -> Result<Imported, ImportError> {
    target.check_canvas()?;
    let source = vertices.name.clone();
    let count = vertex_count(layout, vertices.len, &source)?;
    if index.is_none() && count % 3 != 0 {
        return Err(ImportError::new(
            &source,
            format!(
                "{}: a triangle list without an index buffer needs a multiple of 3 ({} and {} left over); pass --count or --index",
                counted(count as u64, "vertex", "vertices"),
                counted((count / 3) as u64, "triangle", "triangles"),
                counted((count % 3) as u64, "vertex", "vertices")
            ),
        ));
    }
    let index_plan = match &index {
        Some((file, kind)) => Some((index_count(file, *kind)?, file.name.clone(), *kind)),
        None => None,
    };
    let read = read_vertices(vertices.reader, layout, count, &source)?;
    let order: Vec<usize> = match index {
        Some((file, kind)) => {
            let name = file.name.clone();
            let n = index_plan.as_ref().map_or(0, |p| p.0);
            read_indices(file.reader, kind, n, count, &name)?
        }
        None => (0..count).collect(),
    };
    let triangle_count = order.len() / 3;
    let mut exact = Vec::with_capacity(order.len());
    for &k in &order {
        exact.push(read.exact(k, &source)?);
    }
    let (scene, space_text) = match space {
        Space::Clip => (target.clip_scene(clip_triangles(exact))?, target.describe(true)),
        Space::Window => {
            let mut triangles = Vec::with_capacity(triangle_count);
            let mut it = exact.into_iter().map(|[x, y, _, _]| Point::new(x, y));
            while let (Some(a), Some(b), Some(c)) = (it.next(), it.next(), it.next()) {
                triangles.push(Triangle::new(a, b, c));
            }
            (target.window_scene(triangles)?, target.describe(false))
        }
    };
    let indexed = index_plan
        .map(|(n, name, kind)| format!(" by {n} {} indices of {name}", kind.name()))
        .unwrap_or_default();
    let summary = format!(
        "{source}: {} from {} (offset {}, stride {}, {} components){indexed}; {space_text}",
        counted(triangle_count as u64, "triangle", "triangles"),
        counted(count as u64, "vertex", "vertices"),
        layout.offset,
        layout.stride,
        layout.components,
    );
    Ok(Imported { scene, summary })
}

/// The vertex count the layout reads from a file of `len` bytes, checked: the layout
/// itself, the file long enough, the count within [`MAX_VERTICES`].
fn vertex_count(layout: &Layout, len: u64, source: &str) -> Result<usize, ImportError> {
    let err = |message: String| ImportError::new(source, message);
    if !(2..=4).contains(&layout.components) {
        return Err(err(format!(
            "{} components per vertex (expected 2, 3 or 4)",
            layout.components
        )));
    }
    let size = 4 * u64::from(layout.components);
    if layout.stride < size {
        return Err(err(format!(
            "the stride {} is smaller than a vertex of {} f32 components ({size} bytes)",
            layout.stride, layout.components
        )));
    }
    let count = match layout.count {
        Some(count) => count,
        None if len < layout.offset.saturating_add(size) => 0,
        None => (len - layout.offset - size) / layout.stride + 1,
    };
    if count == 0 {
        return Err(err(format!(
            "holds no vertex: {len} bytes, the first vertex ({size} bytes) at offset {}",
            layout.offset
        )));
    }
    let needed = u128::from(layout.offset) + u128::from(layout.stride) * u128::from(count - 1) + u128::from(size);
    if needed > u128::from(len) {
        return Err(err(format!(
            "truncated: {count} vertices at offset {}, stride {}, {} components need {needed} bytes, the file has {len}",
            layout.offset, layout.stride, layout.components
        )));
    }
    usize::try_from(count)
        .ok()
        .filter(|&c| c <= MAX_VERTICES)
        .ok_or_else(|| err(format!("{count} vertices: more than {MAX_VERTICES} (pass --count)")))
}

/// The number of indices in `file`, checked: a whole number of indices, in threes, within
/// [`MAX_TRIANGLES`] triangles.
fn index_count<S>(file: &RawFile<S>, kind: IndexType) -> Result<usize, ImportError> {
    let err = |message: String| ImportError::new(&file.name, message);
    let size = kind.size();
    if file.len % size != 0 {
        return Err(err(format!(
            "{} bytes is not a whole number of {} indices ({size} bytes each)",
            file.len,
            kind.name()
        )));
    }
    let n = file.len / size;
    if n == 0 {
        return Err(err("holds no index".into()));
    }
    if n % 3 != 0 {
        return Err(err(format!(
            "{n} indices: a triangle list needs a multiple of 3 ({} and {} left over)",
            counted(n / 3, "triangle", "triangles"),
            counted(n % 3, "index", "indices")
        )));
    }
    usize::try_from(n / 3)
        .ok()
        .filter(|&t| t <= MAX_TRIANGLES)
        .map(|t| 3 * t)
        .ok_or_else(|| {
            err(format!(
                "{} triangles: more than the scene limit of {MAX_TRIANGLES}",
                n / 3
            ))
        })
}

/// Reads `count` vertices of `layout` (already checked against the file's length).
fn read_vertices<R: Read>(reader: R, layout: &Layout, count: usize, source: &str) -> Result<Vertices, ImportError> {
    let fail = |e: io::Error| ImportError::new(source, format!("cannot read: {e}"));
    let mut reader = BufReader::new(reader);
    skip(&mut reader, layout.offset).map_err(fail)?;
    let size = 4 * layout.components as usize;
    let gap = layout.stride - size as u64;
    let mut floats = Vec::with_capacity(count);
    let mut bytes = [0u8; 16];
    for k in 0..count {
        reader.read_exact(&mut bytes[..size]).map_err(fail)?;
        let f = |c: usize| f32::from_le_bytes(bytes[4 * c..4 * c + 4].try_into().expect("4 bytes"));
        let mut v = [0.0, 0.0, 0.0, 1.0];
        for (c, slot) in v.iter_mut().enumerate().take(layout.components as usize) {
            *slot = f(c);
        }
        floats.push(v);
        if k + 1 < count {
            skip(&mut reader, gap).map_err(fail)?;
        }
    }
    Ok(Vertices {
        floats,
        layout: *layout,
    })
}

/// Reads `n` indices of `kind`, each checked against `vertices`.
fn read_indices<S: Read>(
    reader: S,
    kind: IndexType,
    n: usize,
    vertices: usize,
    source: &str,
) -> Result<Vec<usize>, ImportError> {
    let mut reader = BufReader::new(reader);
    let mut out = Vec::with_capacity(n);
    let mut bytes = [0u8; 4];
    let size = match kind {
        IndexType::U16 => 2,
        IndexType::U32 => 4,
    };
    for position in 0..n {
        reader
            .read_exact(&mut bytes[..size])
            .map_err(|e| ImportError::new(source, format!("cannot read: {e}")))?;
        let index = match kind {
            IndexType::U16 => u32::from(u16::from_le_bytes([bytes[0], bytes[1]])),
            IndexType::U32 => u32::from_le_bytes(bytes),
        };
        match usize::try_from(index).ok().filter(|&i| i < vertices) {
            Some(i) => out.push(i),
            None => {
                return Err(ImportError::new(
                    source,
                    format!("index {index} at position {position} of {source} is out of range ({vertices} vertices)"),
                ))
            }
        }
    }
    Ok(out)
}

/// Skips `n` bytes of `reader`; an error if it ends first.
fn skip<R: Read>(reader: &mut R, n: u64) -> io::Result<()> {
    let skipped = io::copy(&mut reader.take(n), &mut io::sink())?;
    if skipped < n {
        return Err(io::Error::new(io::ErrorKind::UnexpectedEof, "the file ended early"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layout(components: u32, stride: u64, offset: u64, count: Option<u64>) -> Layout {
        Layout {
            components,
            stride,
            offset,
            count,
        }
    }

    #[test]
    fn the_count_fills_the_file_and_a_short_file_is_named() {
        assert_eq!(vertex_count(&layout(4, 20, 4, None), 4 + 20 * 5 + 16, "f").unwrap(), 6);
        assert_eq!(vertex_count(&layout(4, 20, 4, None), 4 + 20 * 5 + 15, "f").unwrap(), 5);
        let e = vertex_count(&layout(2, 8, 0, Some(3)), 23, "f").unwrap_err();
        assert_eq!(
            e.to_string(),
            "f: truncated: 3 vertices at offset 0, stride 8, 2 components need 24 bytes, the file has 23"
        );
        assert!(vertex_count(&layout(5, 20, 0, None), 100, "f").is_err());
        assert!(vertex_count(&layout(2, 4, 0, Some(u64::MAX)), u64::MAX, "f").is_err());
    }
}
