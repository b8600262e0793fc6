//! `rasterproof import`: RenderDoc's mesh CSV and raw f32 buffers become the scene their
//! floats say, exactly. Expected window positions are derived by hand from each API's
//! viewport transform; coverage is compared with a hand-written scene of the same
//! triangles; every bad input gets its one-line error; the fixtures in
//! `tests/fixtures/import/` (their provenance in its README) are read as the user's files.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use num_bigint::BigInt;
use num_rational::BigRational;
use rasterproof::clip::homogeneous::to_window_exact;
use rasterproof::convention::Preset;
use rasterproof::geom::{Point, Triangle};
use rasterproof::import::raw::{import_raw, IndexType, Layout, RawFile, Space};
use rasterproof::import::renderdoc::{import_csv, CsvOptions};
use rasterproof::import::{ApiViewport, ImportError, ImportTarget, Imported};
use rasterproof::model::{render, Model};
use rasterproof::scene::{parse_scene, Scene};

use crate::tempdir;

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/import")
        .join(name)
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fn target(width: u32, height: u32, preset: Preset, viewport: Option<&str>) -> ImportTarget {
    ImportTarget {
        width,
        height,
        preset,
        viewport: viewport.map(|v| ApiViewport::parse(v).unwrap()),
    }
}

fn csv_text(text: &str, options: &CsvOptions) -> Result<Imported, ImportError> {
    import_csv(text.as_bytes(), "m.csv", options, &target(8, 8, Preset::D3d11, None))
}

fn csv_file(name: &str, target: &ImportTarget) -> Imported {
    let bytes = std::fs::read(fixture(name)).unwrap();
    import_csv(&bytes[..], name, &CsvOptions::default(), target).unwrap()
}

/// An in-memory file.
fn file<'a>(name: &str, bytes: &'a [u8]) -> RawFile<&'a [u8]> {
    RawFile {
        name: name.to_string(),
        len: bytes.len() as u64,
        reader: bytes,
    }
}

/// A raw import of in-memory buffers named pos.bin and idx.bin, on an 8x8 d3d11 canvas.
fn raw(
    vertices: &[u8],
    layout: Layout,
    index: Option<(&[u8], IndexType)>,
    space: Space,
) -> Result<Imported, ImportError> {
    let index = index.map(|(bytes, kind)| (file("idx.bin", bytes), kind));
    import_raw(
        file("pos.bin", vertices),
        &layout,
        index,
        space,
        &target(8, 8, Preset::D3d11, None),
    )
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|f| f.to_le_bytes()).collect()
}

fn layout(components: u32, stride: u64, offset: u64, count: Option<u64>) -> Layout {
    Layout {
        components,
        stride,
        offset,
        count,
    }
}

fn tri(v: [(i64, i64); 3]) -> Triangle {
    let [a, b, c] = v.map(|(x, y)| Point::from_ints(x, y));
    Triangle::new(a, b, c)
}

/// The window points of a scene's clip-space triangles, through its own viewport.
fn window_points(scene: &Scene) -> Vec<[Point; 3]> {
    let vp = scene.viewport();
    scene
        .clip_space_triangles
        .iter()
        .map(|t| {
            let mut k = 0;
            t.clone().map(|v| {
                k += 1;
                to_window_exact(&v, k, &vp).unwrap().point
            })
        })
        .collect()
}

/// `scene` and `expected` (window triangles on the same canvas and preset) cover the same
/// pixels with the same ids, under the exact model, and cover something.
fn assert_same_coverage(scene: &Scene, expected: Vec<Triangle>) {
    let mut hand = Scene::new(scene.width, scene.height, expected);
    hand.preset = scene.preset;
    let ours = render(&scene.primitives(), &scene.target().unwrap(), Model::Exact).unwrap();
    let theirs = render(&hand.primitives(), &hand.target().unwrap(), Model::Exact).unwrap();
    assert!(theirs.covered_pixels() > 0);
    assert!(
        ours == theirs,
        "the imported scene covers other pixels than the hand-written one"
    );
}

// --- RenderDoc's CSV -------------------------------------------------------------------

/// The D3D11 fixture: SV_Position, a TEXCOORD0 column, CRLF line ends.
#[test]
fn a_d3d11_csv_lands_where_the_d3d_viewport_transform_puts_it() {
    let imported = csv_file("renderdoc_d3d11.csv", &target(8, 8, Preset::D3d11, None));
    let scene = &imported.scene;
    assert_eq!(scene.clip_space_triangles.len(), 2);
    // Row 5 (VTX 3) is " 1.00, -1.00,  0.50,  2.00", read exactly.
    assert_eq!(
        scene.clip_space_triangles[1][0].pos,
        [q(1, 1), q(-1, 1), q(1, 2), q(2, 1)]
    );
    // D3D's viewport transform (y down, NDC +1 at the top) on the 8x8 viewport at 0,0:
    // x_win = 0 + (x/w + 1) * 8/2, y_win = 0 + (1 - y/w) * 8/2. For (1, -1, 0.5, 2): NDC
    // (1/2, -1/2), so x_win = 3/2 * 4 = 6 and y_win = 3/2 * 4 = 6. For (0.5, 1, 0, 1):
    // (3/2 * 4, 0 * 4) = (6, 0); for (-1, -0.5, 0, 1): (0, 3/2 * 4) = (0, 6).
    let points = window_points(scene);
    assert_eq!(points[1][0], Point::from_ints(6, 6));
    assert_eq!(points[0][1], Point::from_ints(6, 0));
    assert_eq!(points[0][2], Point::from_ints(0, 6));
    assert_same_coverage(
        scene,
        vec![tri([(0, 0), (6, 0), (0, 6)]), tri([(6, 6), (6, 0), (0, 6)])],
    );
    assert_eq!(
        imported.summary,
        "renderdoc_d3d11.csv: 2 triangles from rows 2-7, columns SV_Position.x, SV_Position.y, SV_Position.z, \
         SV_Position.w (each value the f32 its text rounds to, exactly); clip space, preset d3d11, viewport 0,0,8,8"
    );
}

/// The same rows under vulkan: NDC y points down, so the triangles are mirrored.
#[test]
fn a_vulkan_csv_keeps_ndc_y_down() {
    let scene = csv_file("renderdoc_d3d11.csv", &target(8, 8, Preset::Vulkan, None)).scene;
    // Vulkan: y_win = y + (y/w + 1) * h/2; (0.5, 1, 0, 1) -> (6, 2 * 4) = (6, 8).
    assert_eq!(window_points(&scene)[0][1], Point::from_ints(6, 8));
    assert_same_coverage(
        &scene,
        vec![tri([(0, 8), (6, 8), (0, 2)]), tri([(6, 2), (6, 8), (0, 2)])],
    );
    // A flipped Vulkan viewport (y = 8, height -8) is D3D's picture again.
    let flipped = csv_file("renderdoc_d3d11.csv", &target(8, 8, Preset::Vulkan, Some("0,8,8,-8"))).scene;
    assert_eq!(window_points(&flipped)[0][1], Point::from_ints(6, 0));
}

/// The GL fixture: gl_Position; glViewport's y counts up from the bottom of the window.
#[test]
fn a_gl_csv_counts_the_viewport_from_the_bottom() {
    let scene = csv_file("renderdoc_gl.csv", &target(8, 10, Preset::Gl, Some("0,2,8,4"))).scene;
    // glViewport(0, 2, 8, 4) in a 10-row window: GL rows 2..6 from the bottom, which are
    // rows 10-6 = 4 .. 10-2 = 8 of the y-down image. NDC (-1, -1) is the viewport's
    // bottom-left: GL (0, 2), image (0, 8); (1, -1): (8, 8); (0, 1) its top middle: GL
    // (4, 6), image (4, 4).
    assert_eq!(
        window_points(&scene)[0],
        [Point::from_ints(0, 8), Point::from_ints(8, 8), Point::from_ints(4, 4)]
    );
    assert_same_coverage(&scene, vec![tri([(0, 8), (8, 8), (4, 4)])]);
}

#[test]
fn the_position_column_is_chosen_by_name_and_quotes_and_spaces_are_read() {
    let text = "\"VTX\",\"IDX\",\"POSITION.x\",\"POSITION.y\",\"POSITION.z\",\"POSITION.w\",\"pos2.x\",\"pos2.y\",\"pos2.z\",\"pos2.w\"\n\
                0, 0, \"-1\", -1, 0, 1,   0, 0, 0, 1\n\
                1, 1, 1, -1, 0, 1,        1, 0, 0, 1\n\
                2, 2, -1, 1, 0, 1,        0, 1, 0, 1\n";
    let default = csv_text(text, &CsvOptions::default()).unwrap();
    assert_eq!(default.scene.clip_space_triangles[0][0].pos[0], q(-1, 1));
    let named = CsvOptions {
        position: Some("POS2".into()),
        exact_decimal: false,
    };
    let second = csv_text(text, &named).unwrap();
    assert_eq!(second.scene.clip_space_triangles[0][1].pos[0], q(1, 1));
    assert!(second.summary.contains("columns pos2.x, pos2.y, pos2.z, pos2.w"));
}

#[test]
fn a_csv_value_is_the_f32_its_text_rounds_to_unless_exact_decimal() {
    let text = "VTX, IDX, SV_Position.x, SV_Position.y, SV_Position.z, SV_Position.w\n\
                0, 0, 0.1, 0, 0, 1\n1, 1, 1, 0, 0, 1\n2, 2, 0, 1, 0, 1\n";
    let f32_read = csv_text(text, &CsvOptions::default()).unwrap();
    assert_eq!(f32_read.scene.clip_space_triangles[0][0].pos[0], q(13421773, 134217728));
    let exact = CsvOptions {
        position: None,
        exact_decimal: true,
    };
    let decimal = csv_text(text, &exact).unwrap();
    assert_eq!(decimal.scene.clip_space_triangles[0][0].pos[0], q(1, 10));
}

// --- raw buffers ----------------------------------------------------------------------

/// The committed fixtures are the bytes their README's script writes.
#[test]
fn the_raw_fixtures_are_what_their_readme_says() {
    let mut pos = vec![0xff; 8];
    for v in [
        [-1.0, 1.0, 0.1, 1.0],
        [1.0, 1.0, 0.1, 1.0],
        [-1.0, -1.0, 0.5, 1.0],
        [1.0, -1.0, 0.25, 1.0f32],
    ] {
        pos.extend(f32_bytes(&v));
        pos.extend([0xff; 4]);
    }
    assert_eq!(std::fs::read(fixture("pos.bin")).unwrap(), pos);
    let idx: Vec<u8> = [0u16, 1, 2, 2, 1, 3].iter().flat_map(|i| i.to_le_bytes()).collect();
    assert_eq!(std::fs::read(fixture("idx.bin")).unwrap(), idx);
}

/// pos.bin + idx.bin: the NDC square in two triangles covers the 8x8 canvas once, and
/// the f32 0.1 in it is 13421773/134217728, not 1/10.
#[test]
fn a_raw_buffer_with_u16_indices_is_read_exactly() {
    let pos = std::fs::read(fixture("pos.bin")).unwrap();
    let idx = std::fs::read(fixture("idx.bin")).unwrap();
    let imported = raw(&pos, layout(4, 20, 8, None), Some((&idx, IndexType::U16)), Space::Clip).unwrap();
    let scene = &imported.scene;
    let z = &scene.clip_space_triangles[0][0].pos[2];
    assert_eq!(*z, q(13421773, 134217728));
    assert_ne!(*z, q(1, 10));
    // The index order 2 1 3: vertex 3 is (1, -1, 0.25, 1), window (8, 8).
    assert_eq!(
        scene.clip_space_triangles[1][2].pos,
        [q(1, 1), q(-1, 1), q(1, 4), q(1, 1)]
    );
    let coverage = render(&scene.primitives(), &scene.target().unwrap(), Model::Exact).unwrap();
    assert_eq!(coverage.covered_pixels(), 64);
    assert_eq!(coverage.double_covered().count(), 0);
    assert_same_coverage(
        scene,
        vec![tri([(0, 0), (8, 0), (0, 8)]), tri([(0, 8), (8, 0), (8, 8)])],
    );
    assert_eq!(
        imported.summary,
        "pos.bin: 2 triangles from 4 vertices (offset 8, stride 20, 4 components) by 6 u16 indices of idx.bin; \
         clip space, preset d3d11, viewport 0,0,8,8"
    );
}

#[test]
fn window_space_reads_pixels_and_short_vertices_get_z_0_and_w_1() {
    // x y pairs, packed, in threes: (0, 0) (8, 0) (0, 8.5).
    let bytes = f32_bytes(&[0.0, 0.0, 8.0, 0.0, 0.0, 8.5]);
    let window = raw(&bytes, layout(2, 8, 0, None), None, Space::Window).unwrap();
    assert_eq!(window.scene.triangles()[0].v[2], Point::new(q(0, 1), q(17, 2)));
    assert!(window.scene.clip_space_triangles.is_empty());
    let clip = raw(&bytes, layout(2, 8, 0, None), None, Space::Clip).unwrap();
    assert_eq!(
        clip.scene.clip_space_triangles[0][1].pos,
        [q(8, 1), q(0, 1), q(0, 1), q(1, 1)]
    );
    // u32 indices reuse a vertex.
    let idx: Vec<u8> = [2u32, 1, 0].iter().flat_map(|i| i.to_le_bytes()).collect();
    let indexed = raw(
        &bytes,
        layout(2, 8, 0, None),
        Some((&idx, IndexType::U32)),
        Space::Window,
    )
    .unwrap();
    assert_eq!(indexed.scene.triangles()[0].v[0], Point::new(q(0, 1), q(17, 2)));
}

// --- round trips ----------------------------------------------------------------------

#[test]
fn an_imported_scene_parses_back_to_itself() {
    let csv = csv_file("renderdoc_gl.csv", &target(8, 10, Preset::Gl, Some("0,2,8,4"))).scene;
    let back = parse_scene(&csv.to_json(), "back.json").unwrap();
    assert_eq!(back, csv);
    let bytes = f32_bytes(&[0.1, 0.0, 8.0, 1e-40, 0.0, 8.5]);
    let window = raw(&bytes, layout(2, 8, 0, None), None, Space::Window).unwrap().scene;
    assert_eq!(parse_scene(&window.to_json(), "back.json").unwrap(), window);
}

fn bin() -> Command {
    Command::cargo_bin("rasterproof").unwrap()
}

/// The CLI writes the scene to -o, its summary to stderr, and `render` reads the file
/// back: the same pixels as the hand-written scene of the same triangles.
#[test]
fn import_then_render_through_the_binary() {
    let dir = tempdir::Dir::new("import-cli");
    let out = dir.path().join("scene.json");
    let csv = fixture("renderdoc_d3d11.csv");
    let run = bin()
        .args(["import", csv.to_str().unwrap(), "--width", "8", "--height", "8", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(run.stdout.is_empty());
    let stderr = String::from_utf8(run.stderr).unwrap();
    assert!(
        stderr.contains(": 2 triangles from rows 2-7, columns SV_Position.x, SV_Position.y"),
        "{stderr}"
    );
    let hand = dir.path().join("hand.json");
    let hand_scene = Scene::new(8, 8, vec![tri([(0, 0), (6, 0), (0, 6)]), tri([(6, 6), (6, 0), (0, 6)])]);
    std::fs::write(&hand, hand_scene.to_json()).unwrap();
    let pixels = |scene: &Path| {
        let r = bin()
            .args([
                "render",
                scene.to_str().unwrap(),
                "--format",
                "json",
                "--model",
                "exact",
            ])
            .output()
            .unwrap();
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
        String::from_utf8(r.stdout).unwrap()
    };
    let ours = pixels(&out);
    assert!(ours.contains("\"pixels\":[["));
    assert_eq!(ours, pixels(&hand));

    // Raw buffers to stdout.
    let r = bin()
        .args([
            "import",
            "--raw",
            fixture("pos.bin").to_str().unwrap(),
            "--offset",
            "8",
            "--stride",
            "20",
        ])
        .args(["--index", fixture("idx.bin").to_str().unwrap(), "--index-type", "u16"])
        .args(["--width", "8", "--height", "8"])
        .output()
        .unwrap();
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let scene = parse_scene(std::str::from_utf8(&r.stdout).unwrap(), "stdout").unwrap();
    assert_eq!(scene.clip_space_triangles.len(), 2);
    assert!(String::from_utf8_lossy(&r.stderr).contains("by 6 u16 indices of"));
}

/// Bad input through the CLI: exit 2, one line naming the file, and no output file.
#[test]
fn bad_input_writes_no_scene() {
    let dir = tempdir::Dir::new("import-bad");
    let csv = dir.path().join("bad.csv");
    std::fs::write(
        &csv,
        "VTX, IDX, SV_Position.x, SV_Position.y, SV_Position.z, SV_Position.w\n0, 0, 1, 1, 0, nan\n",
    )
    .unwrap();
    let out = dir.path().join("scene.json");
    let r = bin()
        .args(["import", csv.to_str().unwrap(), "--width", "8", "--height", "8", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(r.status.code(), Some(2));
    let stderr = String::from_utf8(r.stderr).unwrap();
    assert!(
        stderr.ends_with("bad.csv: row 2, SV_Position.w: \"nan\" is not a finite number\n"),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1);
    assert!(!out.exists());
    let both = bin()
        .args([
            "import",
            csv.to_str().unwrap(),
            "--raw",
            "x.bin",
            "--width",
            "8",
            "--height",
            "8",
        ])
        .output()
        .unwrap();
    assert_eq!(both.status.code(), Some(2));
}

// --- bad input, each error's text -------------------------------------------------------

const HEADER: &str = "VTX, IDX, SV_Position.x, SV_Position.y, SV_Position.z, SV_Position.w, TEXCOORD0.x\n";

fn csv_error(body: &str) -> String {
    csv_text(&format!("{HEADER}{body}"), &CsvOptions::default())
        .unwrap_err()
        .to_string()
}

#[test]
fn csv_errors_name_the_row_the_column_and_the_value() {
    let ok = "0, 0, 0, 0, 0, 1, 0\n1, 1, 1, 0, 0, 1, 0\n";
    assert_eq!(
        csv_error(&format!("{ok}2, 2, 0, 1, 0\n")),
        "m.csv: row 4: no SV_Position.w column (the row has 5 fields, the header 7)"
    );
    assert_eq!(
        csv_error(&format!("{ok}2, 2, 0, 1, 0, nan, 0\n")),
        "m.csv: row 4, SV_Position.w: \"nan\" is not a finite number"
    );
    assert_eq!(
        csv_error(&format!("{ok}2, 2, 0, inf, 0, 1, 0\n")),
        "m.csv: row 4, SV_Position.y: \"inf\" is not a finite number"
    );
    assert_eq!(
        csv_error(&format!("{ok}2, 2, 0, ---, 0, 1, 0\n")),
        "m.csv: row 4, SV_Position.y: \"---\" is not a number"
    );
    assert_eq!(
        csv_error(&format!("{ok}2, 2, 0, 1, 0, 1, 0\n3, 3, 0, 1, 0, 1, 0\n")),
        "m.csv: 4 vertex rows: a triangle list needs a multiple of 3 rows (1 triangle and 1 row left over)"
    );
    assert_eq!(csv_error(""), "m.csv: has a header row but no vertex rows");
    let e = |text: &str| csv_text(text, &CsvOptions::default()).unwrap_err().to_string();
    assert_eq!(
        e(""),
        "m.csv: is empty (RenderDoc's export starts with a header row: VTX, IDX, ...)"
    );
    assert_eq!(
        e("0, 0, 1, 2, 3, 4\n"),
        "m.csv: row 1 is not a header row (0, 0, 1, 2, 3, 4); RenderDoc's export starts with VTX, IDX, <name>.x, ..."
    );
    assert_eq!(
        e("VTX, IDX, POSITION.x, POSITION.y, POSITION.z, TEXCOORD0.x\n"),
        "m.csv: no position columns: none of SV_Position, gl_Position, gl_PerVertex.gl_Position, POSITION has \
         .x .y .z .w columns; the header has VTX, IDX, POSITION.x, POSITION.y, POSITION.z, TEXCOORD0.x \
         (name the position with --position NAME)"
    );
}

#[test]
fn raw_errors_name_the_file_the_offset_and_the_value() {
    let twelve = f32_bytes(&[0.0; 12]);
    let err = |bytes: &[u8], l: Layout, index: Option<(&[u8], IndexType)>| {
        raw(bytes, l, index, Space::Clip).unwrap_err().to_string()
    };
    assert_eq!(
        err(&twelve[..44], layout(4, 16, 0, Some(3)), None),
        "pos.bin: truncated: 3 vertices at offset 0, stride 16, 4 components need 48 bytes, the file has 44"
    );
    assert_eq!(
        err(&twelve, layout(4, 12, 0, None), None),
        "pos.bin: the stride 12 is smaller than a vertex of 4 f32 components (16 bytes)"
    );
    assert_eq!(
        err(&twelve, layout(2, 8, 0, Some(4)), None),
        "pos.bin: 4 vertices: a triangle list without an index buffer needs a multiple of 3 (1 triangle and 1 vertex \
         left over); pass --count or --index"
    );
    let mut nan = twelve.clone();
    nan[4 * 5..4 * 6].copy_from_slice(&f32::NAN.to_le_bytes());
    assert_eq!(
        err(&nan, layout(2, 8, 0, Some(3)), None),
        "pos.bin: vertex 2, y (byte 20): NaN is not a finite number"
    );
    let idx: Vec<u8> = [0u16, 1, 2, 2, 1, 17].iter().flat_map(|i| i.to_le_bytes()).collect();
    assert_eq!(
        err(&twelve, layout(4, 16, 0, None), Some((&idx, IndexType::U16))),
        "idx.bin: index 17 at position 5 of idx.bin is out of range (3 vertices)"
    );
    assert_eq!(
        err(&twelve, layout(4, 16, 0, None), Some((&idx[..11], IndexType::U16))),
        "idx.bin: 11 bytes is not a whole number of u16 indices (2 bytes each)"
    );
    assert_eq!(
        err(&twelve, layout(4, 16, 0, None), Some((&idx[..8], IndexType::U16))),
        "idx.bin: 4 indices: a triangle list needs a multiple of 3 (1 triangle and 1 index left over)"
    );
}

/// More triangles than a scene may hold is refused from the lengths alone, before a byte
/// is read.
#[test]
fn more_triangles_than_the_scene_limit_are_refused_unread() {
    use rasterproof::scene::parse::MAX_TRIANGLES;
    let over = 3 * (MAX_TRIANGLES as u64 + 1);
    let nothing = |name: &str, len: u64| RawFile {
        name: name.to_string(),
        len,
        reader: std::io::empty(),
    };
    let t = target(8, 8, Preset::D3d11, None);
    let e = import_raw(
        nothing("pos.bin", 8 * over),
        &layout(2, 8, 0, None),
        None::<(RawFile<std::io::Empty>, _)>,
        Space::Clip,
        &t,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "pos.bin: {over} vertices: more than {} (pass --count)",
            3 * MAX_TRIANGLES
        )
    );
    let e = import_raw(
        nothing("pos.bin", 24),
        &layout(2, 8, 0, None),
        Some((nothing("idx.bin", 4 * over), IndexType::U32)),
        Space::Clip,
        &t,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "idx.bin: {} triangles: more than the scene limit of {MAX_TRIANGLES}",
            MAX_TRIANGLES + 1
        )
    );
}
