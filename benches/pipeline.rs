//! The whole pipeline as a user runs it: `rasterproof render SCENE --model M --ids-out
//! IDS.png` (the binary, one process per run: read, parse, prepare, draw, write the PNG),
//! against a baseline of the same file read into `serde_json::Value` in this process (the
//! cost of merely reading the JSON). Round-robin, median of `REPS` runs; the ratio to the
//! baseline is the figure (the seconds depend on the machine and its load).
//!
//! Scenes: N small triangles (each within 4 px of a random point) on a 1024 x 1024 canvas,
//! every coordinate a 3-decimal number, as a capture exported to JSON reads.
//!
//! `cargo bench --bench pipeline` (N = 100k and 1M; `PIPELINE_SIZES=100000` for one).
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

fn main() {
    let dir: PathBuf = std::env::temp_dir().join("rp-pipeline");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let sizes: Vec<usize> = std::env::var("PIPELINE_SIZES")
        .map(|s| s.split(',').map(|n| n.trim().parse().expect("a size")).collect())
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
    }
}
