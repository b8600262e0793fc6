//! Differential test of `rasterproof::line::bresenham` against the `line_drawing` crate
//! (v1), on deterministic random integer lines (lengths 0..200, all octants).
//!
//! Every pixel is compared step by step (same major-axis coordinate) and each difference is
//! explained against the exact ideal line (`rasterproof::line::exact::ideal`):
//!
//! - `line_drawing::Midpoint` (the midpoint algorithm, fed the integer endpoints as f64)
//!   differs from our Bresenham only at exact ties, where it picks the other candidate:
//!   it is our `BresenhamTie::Step` in every octant (asserted).
//! - `line_drawing::Bresenham` is *not* a midpoint Bresenham: its error term starts at
//!   `dy - dx` instead of `dy - dx/2`, so on its octant-normalised frame it draws
//!   `floor(k dy / dx)`, the integer at or before the ideal minor coordinate in the
//!   direction of travel, up to (not including) one pixel away from the ideal line. At exact
//!   ties that is the candidate nearer the start (our `Stay`); elsewhere it differs from
//!   both of our conventions whenever the ideal minor coordinate is more than 1/2 past an
//!   integer. Asserted: every `line_drawing::Bresenham` pixel is exactly that
//!   "toward-start floor" of the ideal line, and every difference from our `Stay` is a
//!   non-tie step with `|minor - ideal| > 1/2` for line_drawing's pixel.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use rasterproof::line::exact::{ideal, IdealLine};
use rasterproof::line::{bresenham, Axes, BresenhamTie};

use crate::rng;
use rng::Rng;

/// `n` lines: a start within ±300, a major length in 0..200, a minor length in
/// 0..=major (a quarter of them chosen to make exact ties likely: major even, minor odd),
/// random signs and major axis, so all eight octants (and their boundaries) appear.
fn lines(n: usize, seed: u64) -> Vec<([i64; 2], [i64; 2])> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|_| {
            let a = [rng.range(-300, 300), rng.range(-300, 300)];
            let major = rng.range(0, 199);
            let (major, minor) = if rng.next() % 4 == 0 && major >= 2 {
                // ties: the ideal minor coordinate k * minor / major is a half at
                // k = major / 2 when major is even and minor odd
                let even = major & !1;
                (even, rng.range(0, (even - 1) / 2) * 2 + 1)
            } else {
                (major, rng.range(0, major))
            };
            finish(&mut rng, a, major, minor)
        })
        .collect()
}

fn finish(rng: &mut Rng, a: [i64; 2], major: i64, minor: i64) -> ([i64; 2], [i64; 2]) {
    let sign = |rng: &mut Rng| if rng.next() & 1 == 0 { 1 } else { -1 };
    let (dmaj, dmin) = (sign(rng) * major, sign(rng) * minor);
    let (dx, dy) = if rng.next() & 1 == 0 {
        (dmaj, dmin)
    } else {
        (dmin, dmaj)
    };
    (a, [a[0] + dx, a[1] + dy])
}

/// The octant of `a -> b` in words ("dx+ dy- x-major"); axis-aligned, diagonal and
/// zero-length lines get their own labels.
fn octant(a: [i64; 2], b: [i64; 2]) -> String {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let s = |v: i64| match v.signum() {
        1 => '+',
        -1 => '-',
        _ => '0',
    };
    if dx == 0 && dy == 0 {
        return "point".into();
    }
    if dx == 0 || dy == 0 {
        return "axis-aligned".into();
    }
    if dx.abs() == dy.abs() {
        return "diagonal".into();
    }
    let axis = if dx.abs() > dy.abs() { 'x' } else { 'y' };
    format!("dx{} dy{} {axis}-major", s(dx), s(dy))
}

#[derive(Default, Debug)]
struct Tally {
    lines: u64,
    pixels: u64,
    tie_steps: u64,
    /// line_drawing's pixel at a tie equals our Stay pick / our Step pick.
    tie_stay: u64,
    tie_step: u64,
    /// Differences from our Stay / Step line.
    diff_stay: u64,
    diff_step: u64,
    /// Differences from Stay that are not exact ties.
    non_tie_diff: u64,
}

/// The integer at or before `minor` in the direction of travel on the minor axis.
fn toward_start(minor: &BigRational, minor_sign: i64) -> i64 {
    let v = if minor_sign >= 0 { minor.floor() } else { minor.ceil() };
    v.to_integer().to_i64().unwrap()
}

/// Compares `theirs` with our lines for `a -> b`, step by step. Returns, per step, their
/// minor coordinate (after checking the major coordinates match ours).
fn their_minors(line: &IdealLine, theirs: &[[i64; 2]], what: &str, a: [i64; 2], b: [i64; 2]) -> Vec<i64> {
    assert_eq!(theirs.len(), line.steps.len(), "{what} {a:?} -> {b:?}: pixel count");
    theirs
        .iter()
        .zip(&line.steps)
        .map(|(&p, step)| {
            let (major, minor) = line.axes.split(p);
            assert_eq!(major, step.major, "{what} {a:?} -> {b:?}: major coordinate of {p:?}");
            minor
        })
        .collect()
}

fn tally_step(t: &mut Tally, step: &rasterproof::line::exact::IdealStep, axes: &Axes, theirs: i64, stay: i64, st: i64) {
    t.pixels += 1;
    if step.candidates.len() == 2 {
        t.tie_steps += 1;
        t.tie_stay += u64::from(theirs == step.pick(axes.minor_sign, BresenhamTie::Stay));
        t.tie_step += u64::from(theirs == step.pick(axes.minor_sign, BresenhamTie::Step));
    } else if theirs != stay {
        t.non_tie_diff += 1;
    }
    t.diff_stay += u64::from(theirs != stay);
    t.diff_step += u64::from(theirs != st);
}

fn print_table(title: &str, tallies: &BTreeMap<String, Tally>) {
    println!("{title}");
    println!(
        "  {:<18} {:>6} {:>7} {:>6} {:>8} {:>8} {:>9} {:>9} {:>9}",
        "octant", "lines", "pixels", "ties", "tie=Stay", "tie=Step", "diff Stay", "diff Step", "non-tie"
    );
    for (k, t) in tallies {
        println!(
            "  {:<18} {:>6} {:>7} {:>6} {:>8} {:>8} {:>9} {:>9} {:>9}",
            k, t.lines, t.pixels, t.tie_steps, t.tie_stay, t.tie_step, t.diff_stay, t.diff_step, t.non_tie_diff
        );
    }
}

const CASES: usize = 1200;

#[test]
fn line_drawing_midpoint_is_our_step_convention() {
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    for (a, b) in lines(CASES, 0x5eed_0001) {
        let line = ideal(a, b);
        let stay = bresenham::pixels(a, b, BresenhamTie::Stay);
        let step = bresenham::pixels(a, b, BresenhamTie::Step);
        #[allow(clippy::cast_precision_loss)] // |coordinates| < 600: exact in f64
        let f = |p: [i64; 2]| (p[0] as f64, p[1] as f64);
        let theirs: Vec<[i64; 2]> = line_drawing::Midpoint::<f64, i64>::new(f(a), f(b))
            .map(|(x, y)| [x, y])
            .collect();
        let minors = their_minors(&line, &theirs, "Midpoint", a, b);
        let t = tallies.entry(octant(a, b)).or_default();
        t.lines += 1;
        for (k, s) in line.steps.iter().enumerate() {
            let ours_stay = line.axes.split(stay[k]).1;
            let ours_step = line.axes.split(step[k]).1;
            let m = minors[k];
            // The claim: equal to our pixel, or an exact tie where it took the other candidate.
            assert!(
                m == ours_stay || (s.candidates.len() == 2 && s.candidates.contains(&m)),
                "Midpoint {a:?} -> {b:?} step {k}: theirs {m}, ideal {} (candidates {:?}), ours (Stay) {ours_stay}",
                s.minor,
                s.candidates
            );
            tally_step(t, s, &line.axes, m, ours_stay, ours_step);
        }
    }
    print_table("line_drawing::Midpoint vs rasterproof Bresenham", &tallies);
    let total_ties: u64 = tallies.values().map(|t| t.tie_steps).sum();
    assert!(
        total_ties > 1000,
        "the generator should produce many ties ({total_ties})"
    );
    for (k, t) in &tallies {
        assert_eq!(t.non_tie_diff, 0, "{k}");
        assert_eq!(t.diff_step, 0, "{k}: Midpoint should equal our Step convention");
    }
}

#[test]
fn line_drawing_bresenham_is_a_floor_walk() {
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    let half = BigRational::new(BigInt::from(1), BigInt::from(2));
    for (a, b) in lines(CASES, 0x5eed_0002) {
        let line = ideal(a, b);
        let stay = bresenham::pixels(a, b, BresenhamTie::Stay);
        let step = bresenham::pixels(a, b, BresenhamTie::Step);
        let theirs: Vec<[i64; 2]> = line_drawing::Bresenham::new((a[0], a[1]), (b[0], b[1]))
            .map(|(x, y)| [x, y])
            .collect();
        let minors = their_minors(&line, &theirs, "Bresenham", a, b);
        let t = tallies.entry(octant(a, b)).or_default();
        t.lines += 1;
        for (k, s) in line.steps.iter().enumerate() {
            let ours_stay = line.axes.split(stay[k]).1;
            let ours_step = line.axes.split(step[k]).1;
            let m = minors[k];
            // Their pixel is the toward-start floor of the ideal line...
            assert_eq!(
                m,
                toward_start(&s.minor, line.axes.minor_sign),
                "Bresenham {a:?} -> {b:?} step {k}: ideal minor {}",
                s.minor
            );
            // ...so it differs from ours (Stay) only where it is more than 1/2 off the line.
            let off = (BigRational::from_integer(BigInt::from(m)) - &s.minor).abs();
            if m != ours_stay {
                assert!(s.candidates.len() == 1 && off > half, "{a:?} -> {b:?} step {k}");
            }
            tally_step(t, s, &line.axes, m, ours_stay, ours_step);
        }
    }
    print_table("line_drawing::Bresenham vs rasterproof Bresenham", &tallies);
    let sum = |f: fn(&Tally) -> u64| tallies.values().map(f).sum::<u64>();
    let (ties, tie_stay, non_tie) = (sum(|t| t.tie_steps), sum(|t| t.tie_stay), sum(|t| t.non_tie_diff));
    println!("  total: {ties} tie steps, {tie_stay} of them = Stay; {non_tie} non-tie differences from Stay");
    assert!(ties > 1000);
    assert_eq!(
        tie_stay, ties,
        "at exact ties line_drawing::Bresenham is our Stay convention"
    );
    // The documented discrepancy (not a tie convention): there are many non-tie differences.
    assert!(non_tie > 0);
}

/// The smallest case of the discrepancy, spelled out: (0,0) -> (3,1) has the ideal
/// minor coordinates 0, 1/3, 2/3, 1; line_drawing::Bresenham draws (2, 0), 2/3 away.
#[test]
fn line_drawing_bresenham_smallest_discrepancy() {
    let theirs: Vec<(i64, i64)> = line_drawing::Bresenham::new((0, 0), (3, 1)).collect();
    assert_eq!(theirs, vec![(0, 0), (1, 0), (2, 0), (3, 1)]);
    for tie in [BresenhamTie::Stay, BresenhamTie::Step] {
        assert_eq!(
            bresenham::pixels([0, 0], [3, 1], tie),
            vec![[0, 0], [1, 0], [2, 1], [3, 1]]
        );
    }
}
