//! The whole pipeline as a user runs it: `rasterproof render SCENE --model M --ids-out
//! IDS.png` (the binary, one process per run: read, parse, prepare, draw, write the PNG),
//! against a baseline of the same file read into `serde_json::Value` in this process (the
//! cost of merely reading the JSON). Round-robin, median of `REPS` runs; the ratio to the
//! baseline is the figure (the seconds depend on the machine and its load).
//!
//! Scenes: N small triangles (each within 4 px of a random point) on a 1024 x 1024 canvas,
//! every coordinate a 3-decimal number, as a capture exported to JSON reads.
//!
//! Then the whole frame on threads: a 16384 x 16384 mesh of about 1M triangles, `fixed`,
//! drawn on one and two threads (`PreparedScene::coverage_parallel`), and `render --jobs`.
//!
//! `cargo bench --features bench --bench pipeline` (N = 100k and 1M; `PIPELINE_SIZES=100000` for one,
//! `PIPELINE_SIZES=` for none, `PIPELINE_FRAME=0` without the frame).
//! Peak memory: `benches/memory.sh`.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

#[path = "../tests/common/rng.rs"]
mod rng;
use rng::Rng;

const REPS: usize = 5;

/// A scene of `n` small triangles, written to `path`.
fn write_scene(path: &Path, n: usize, seed: u64) {
    let mut rng = Rng(seed);
    let mut s = String::with_capacity(n * 70);
    s.push_str("{\"width\":1024,\"height\":1024,\"triangles\":[");
    // In thousandths of a pixel: a point within 1020 px, the vertices within 4 px of it.
    let thousandths = |t: i64| format!("{}.{:03}", t / 1000, t % 1000);
    for k in 0..n {
        if k > 0 {
            s.push(',');
        }
        let (x, y) = (rng.below(1_020_000), rng.below(1_020_000));
        let v: Vec<String> = (0..3)
            .map(|_| {
                let (vx, vy) = (x + rng.below(4000), y + rng.below(4000));
                format!("[{},{}]", thousandths(vx), thousandths(vy))
            })
            .collect();
        s.push_str(&format!("{{\"v\":[{}]}}", v.join(",")));
    }
    s.push_str("]}");
    std::fs::write(path, s).expect("write the scene");
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The baseline: the file read and parsed into `serde_json::Value`.
fn baseline(path: &Path) -> f64 {
    let start = Instant::now();
    let text = std::fs::read_to_string(path).expect("read");
    let value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    std::hint::black_box(&value);
    drop(value);
    start.elapsed().as_secs_f64()
}

/// `render` of `path` by the binary, wall clock.
fn render(path: &Path, model: &str, out: &Path) -> f64 {
    let start = Instant::now();
    let status = Command::new(env!("CARGO_BIN_EXE_rasterproof"))
        .arg("render")
        .arg(path)
        .args(["--model", model, "--ids-out"])
        .arg(out)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("run rasterproof");
    assert!(status.success(), "render {} --model {model} failed", path.display());
    start.elapsed().as_secs_f64()
}

/// The planned engine's setup per triangle (`PlannedTriangle::from_compact`: i128 where
/// the coordinates are small), median of `REPS`, in nanoseconds per triangle.
fn planned_setup(path: &Path) -> f64 {
    let text = std::fs::read_to_string(path).expect("read");
    let scene = rasterproof::scene::parse_scene(&text, "bench").expect("scene");
    let target = scene.target().expect("target");
    let triangles: Vec<_> = scene.triangles.iter().map(|t| t.triangle.clone()).collect();
    let times: Vec<f64> = (0..REPS)
        .map(|_| {
            let start = Instant::now();
            for t in &triangles {
                std::hint::black_box(rasterproof::tri::planned::PlannedTriangle::from_compact(t, &target));
            }
            start.elapsed().as_secs_f64() * 1e9 / triangles.len() as f64
        })
        .collect();
    median(times)
}

/// A mesh of `2 cells^2` triangles over a `side` x `side` canvas (a grid of cells, each
/// cut along a diagonal), vertices on 1/1000 px, written to `path`.
fn write_mesh(path: &Path, side: u32, cells: u32) {
    let mut s = String::with_capacity((cells * cells) as usize * 2 * 80);
    s.push_str(&format!("{{\"width\":{side},\"height\":{side},\"triangles\":["));
    let at = |i: u32| {
        let t = u64::from(i) * u64::from(side) * 1000 / u64::from(cells);
        format!("{}.{:03}", t / 1000, t % 1000)
    };
    let mut first = true;
    for j in 0..cells {
        for i in 0..cells {
            let (x0, x1, y0, y1) = (at(i), at(i + 1), at(j), at(j + 1));
            for tri in [
                [(&x0, &y0), (&x1, &y0), (&x1, &y1)],
                [(&x0, &y0), (&x1, &y1), (&x0, &y1)],
            ] {
                if !first {
                    s.push(',');
                }
                first = false;
                let v: Vec<String> = tri.iter().map(|(x, y)| format!("[{x},{y}]")).collect();
                s.push_str(&format!("{{\"v\":[{}]}}", v.join(",")));
            }
        }
    }
    s.push_str("]}");
    std::fs::write(path, s).expect("write the mesh");
}

/// The whole-frame figure: a 16384 x 16384 mesh of 2 x 708^2 (about 1M) triangles drawn by
/// `fixed` on 1 and 2 threads, in this process (prepare once, then the drawing alone) and
/// as `render --jobs N` (the whole process, which also reads the 66 MB file).
fn frame(dir: &Path) {
    let path = dir.join("mesh-16384.json");
    write_mesh(&path, 16384, 708);
    let text = std::fs::read_to_string(&path).expect("read");
    let scene = rasterproof::scene::parse_scene(&text, "mesh").expect("scene");
    drop(text);
    let target = scene.target().expect("target");
    let prepared = rasterproof::model::prepare(&scene.primitives(), &target, rasterproof::model::Model::Fixed)
        .expect("fixed takes the mesh");
    drop(scene);
    let (mut one, mut two) = (Vec::new(), Vec::new());
    let (mut whole_one, mut whole_two) = (Vec::new(), Vec::new());
    for _ in 0..REPS {
        for (jobs, times) in [(1, &mut one), (2, &mut two)] {
            let start = Instant::now();
            let c = prepared.coverage_parallel(&target, jobs, &|| {});
            times.push(start.elapsed().as_secs_f64());
            std::hint::black_box(c.covered_pixels());
        }
        for (jobs, times) in [("1", &mut whole_one), ("2", &mut whole_two)] {
            let start = Instant::now();
            let status = Command::new(env!("CARGO_BIN_EXE_rasterproof"))
                .arg("render")
                .arg(&path)
                .args(["--model", "fixed", "--jobs", jobs])
                .stdout(std::process::Stdio::null())
                .status()
                .expect("run rasterproof");
            assert!(status.success());
            times.push(start.elapsed().as_secs_f64());
        }
    }
    let (a, b) = (median(one), median(two));
    println!(
        "16384^2 mesh, {} triangles, fixed: drawing on 1 thread {a:.3} s, on 2 {b:.3} s: {:.2}x",
        2 * 708 * 708,
        a / b
    );
    let (a, b) = (median(whole_one), median(whole_two));
    println!("  render --jobs 1 {a:.3} s, --jobs 2 {b:.3} s: {:.2}x", a / b);
}

fn main() {
    let dir: PathBuf = std::env::temp_dir().join("rp-pipeline");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let sizes: Vec<usize> = std::env::var("PIPELINE_SIZES")
        .map(|s| {
            s.split(',')
                .filter(|n| !n.trim().is_empty())
                .map(|n| n.trim().parse().expect("a size"))
                .collect()
        })
        .unwrap_or_else(|_| vec![100_000, 1_000_000]);
    println!(
        "pipeline bench: median of {REPS} round-robin runs; ratio = render / serde_json::Value read of the same file"
    );
    for n in sizes {
        let path = dir.join(format!("small-{n}.json"));
        write_scene(&path, n, 7);
        let bytes = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
        let models: &[&str] = if n <= 100_000 {
            &["fixed", "exact", "exact-snapped"]
        } else {
            &["fixed"]
        };
        let mut base = Vec::new();
        let mut times: Vec<Vec<f64>> = vec![Vec::new(); models.len()];
        for _ in 0..REPS {
            base.push(baseline(&path));
            for (m, model) in models.iter().enumerate() {
                times[m].push(render(&path, model, &dir.join("ids.png")));
            }
        }
        let b = median(base);
        println!(
            "{n} small triangles ({:.1} MB): serde_json::Value read {:.3} s",
            bytes as f64 / 1e6,
            b
        );
        for (model, t) in models.iter().zip(times) {
            let t = median(t);
            println!(
                "  render --model {model:<13} --ids-out  {t:.3} s  {:.2}x the baseline",
                t / b
            );
        }
        if n <= 100_000 {
            println!("  planned setup (exact): {:.0} ns per triangle", planned_setup(&path));
        }
    }
    if std::env::var("PIPELINE_FRAME").map_or(true, |v| v != "0") {
        frame(&dir);
    }
}
