//! A pixel's answer as more than one sample: [`SampleCoverage`] keeps, for every sample
//! index of a pattern, which primitives cover that sample of each pixel (one [`Coverage`]
//! per sample index), and writes the forms a GPU's readback of a multisampled target has:
//! the per-pixel sample mask with its owners (JSON), an ids image per sample index (one
//! PNG, the images stacked), and the coverage count as a grey level (what resolving a
//! multisampled target holding one opaque white shape yields).

use std::fmt::Write as _;

use image::{GrayImage, Luma, RgbaImage};

use super::{Coverage, IdOutOfRange};

/// Every sample index's coverage of one canvas.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleCoverage {
    samples: Vec<Coverage>,
}

impl SampleCoverage {
    /// Nothing covered: `count` samples per pixel of a `width x height` canvas.
    pub fn new(width: u32, height: u32, count: usize) -> SampleCoverage {
        SampleCoverage {
            samples: (0..count).map(|_| Coverage::new(width, height)).collect(),
        }
    }

    /// One coverage per sample index, in index order (all of one canvas size).
    ///
    /// # Panics
    /// When `samples` is empty or the sizes differ: a caller's bug.
    pub fn from_samples(samples: Vec<Coverage>) -> SampleCoverage {
        let first = samples.first().expect("at least one sample");
        let size = (first.width(), first.height());
        assert!(
            samples.iter().all(|c| (c.width(), c.height()) == size),
            "one canvas size"
        );
        SampleCoverage { samples }
    }

    /// Covers sample `s` of pixel `(x, y)` with `id`.
    pub fn cover(&mut self, x: u32, y: u32, s: usize, id: u32) {
        super::CoverageSink::cover(&mut self.samples[s], x, y, id);
    }

    /// Samples per pixel.
    pub fn sample_count(&self) -> usize {
        self.samples.len()
    }

    /// Canvas width.
    pub fn width(&self) -> u32 {
        self.samples[0].width()
    }

    /// Canvas height.
    pub fn height(&self) -> u32 {
        self.samples[0].height()
    }

    /// Sample index `s`'s coverage of the canvas.
    pub fn sample(&self, s: usize) -> &Coverage {
        &self.samples[s]
    }

    /// Every sample index's coverage, in index order.
    pub fn samples(&self) -> &[Coverage] {
        &self.samples
    }

    /// The ids covering sample `s` of `(x, y)`, ascending.
    pub fn owners(&self, x: u32, y: u32, s: usize) -> &[u32] {
        self.samples[s].owners(x, y)
    }

    /// Pixel `(x, y)`'s sample mask: bit `s` set when anything covers sample `s`.
    pub fn mask(&self, x: u32, y: u32) -> u64 {
        let bit = |(s, c): (usize, &Coverage)| u64::from(!c.owners(x, y).is_empty()) << s;
        self.samples.iter().enumerate().map(bit).fold(0, |m, b| m | b)
    }

    /// Pixel `(x, y)`'s sample mask for primitive `id` alone.
    pub fn mask_of(&self, x: u32, y: u32, id: u32) -> u64 {
        let bit = |(s, c): (usize, &Coverage)| u64::from(c.owners(x, y).contains(&id)) << s;
        self.samples.iter().enumerate().map(bit).fold(0, |m, b| m | b)
    }

    /// Pixels where some sample is covered, sorted by y then x.
    pub fn covered_pixels(&self) -> Vec<(u32, u32)> {
        let mut out: Vec<(u32, u32)> = self
            .samples
            .iter()
            .flat_map(|c| c.iter().map(|(x, y, _)| (y, x)))
            .collect();
        out.sort_unstable();
        out.dedup();
        out.into_iter().map(|(y, x)| (x, y)).collect()
    }

    /// The machine interface: `{"width":W,"height":H,"samples":N,"pixels":[[x,y,mask,[ids
    /// of sample 0],...,[ids of sample N-1]],...]}`: pixels with some sample covered, by y
    /// then x; `mask` has bit `s` set when sample `s` is covered (a JSON integer: exact in
    /// a double up to 53 samples); each sample's ids ascending, `[]` when uncovered.
    ///
    /// ```
    /// use rasterproof::coverage::samples::SampleCoverage;
    /// let mut c = SampleCoverage::new(3, 2, 2);
    /// c.cover(2, 1, 1, 5);
    /// c.cover(2, 1, 0, 4);
    /// c.cover(2, 1, 1, 4);
    /// assert_eq!(c.to_json(), r#"{"width":3,"height":2,"samples":2,"pixels":[[2,1,3,[4],[4,5]]]}"#);
    /// ```
    pub fn to_json(&self) -> String {
        let mut s = format!(
            r#"{{"width":{},"height":{},"samples":{},"pixels":["#,
            self.width(),
            self.height(),
            self.sample_count()
        );
        for (k, (x, y)) in self.covered_pixels().into_iter().enumerate() {
            let sep = if k == 0 { "" } else { "," };
            let _ = write!(s, "{sep}[{x},{y},{}", self.mask(x, y));
            for c in &self.samples {
                let ids: Vec<String> = c.owners(x, y).iter().map(ToString::to_string).collect();
                let _ = write!(s, ",[{}]", ids.join(","));
            }
            s.push(']');
        }
        s.push_str("]}");
        s
    }

    /// The ids images of every sample index stacked into one: width `W`, height `N * H`,
    /// sample `s`'s ids image (the ids PNG's format, [`super::ids`]) in rows
    /// `s * H .. (s + 1) * H`.
    ///
    /// # Errors
    /// An id the ids PNG cannot hold.
    pub fn to_stacked_ids_image(&self) -> Result<RgbaImage, IdOutOfRange> {
        let (w, h) = (self.width(), self.height());
        let rows = u32::try_from(self.sample_count()).expect("at most 64 samples") * h;
        let mut out = RgbaImage::new(w, rows);
        for (s, c) in (0u32..).zip(&self.samples) {
            let one = c.to_ids_image()?;
            image::imageops::replace(&mut out, &one, 0, i64::from(s * h));
        }
        Ok(out)
    }

    /// How many samples of `(x, y)` anything covers.
    pub fn covered_count(&self, x: u32, y: u32) -> u32 {
        self.mask(x, y).count_ones()
    }

    /// The coverage count as an 8-bit grey level: `round(255 * k / N)` for `k` of `N`
    /// samples covered (halves up): what a box-filter resolve of an opaque white scene on
    /// black gives, rounded to 8 bits as UNORM conversion does.
    pub fn to_count_image(&self) -> GrayImage {
        let n = u32::try_from(self.sample_count()).expect("at most 64 samples");
        let mut out = GrayImage::new(self.width(), self.height());
        for (x, y) in self.covered_pixels() {
            let k = self.covered_count(x, y);
            let level = (510 * k + n) / (2 * n);
            out.put_pixel(x, y, Luma([u8::try_from(level).expect("at most 255")]));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn masks_counts_and_levels_by_hand() {
        let mut c = SampleCoverage::new(2, 1, 4);
        c.cover(0, 0, 0, 1);
        c.cover(0, 0, 2, 1);
        c.cover(0, 0, 2, 3);
        c.cover(1, 0, 3, 3);
        assert_eq!(c.mask(0, 0), 0b0101);
        assert_eq!(c.mask_of(0, 0, 3), 0b0100);
        assert_eq!(c.mask(1, 0), 0b1000);
        assert_eq!(c.covered_count(0, 0), 2);
        // 2 of 4: 127.5 rounds up to 128; 1 of 4: 63.75 to 64.
        assert_eq!(c.to_count_image().as_raw(), &[128, 64]);
        let stacked = c.to_stacked_ids_image().unwrap();
        assert_eq!(stacked.dimensions(), (2, 4));
        assert_eq!(
            stacked.get_pixel(0, 2).0,
            [4, 0, 0, 254],
            "sample 2: ids 1 and 3, the highest is 3"
        );
        assert_eq!(stacked.get_pixel(1, 3).0, [4, 0, 0, 255]);
        assert_eq!(stacked.get_pixel(0, 1).0, [0, 0, 0, 0]);
    }

    #[test]
    fn levels_of_every_count_of_sixteen() {
        let want = [
            0u8, 16, 32, 48, 64, 80, 96, 112, 128, 143, 159, 175, 191, 207, 223, 239, 255,
        ];
        for (k, &level) in want.iter().enumerate() {
            let mut c = SampleCoverage::new(1, 1, 16);
            for s in 0..k {
                c.cover(0, 0, s, 0);
            }
            // 255 k / 16 = 15.9375 k; k = 8: 127.5 -> 128, k = 9: 143.4375 -> 143.
            assert_eq!(c.to_count_image().as_raw()[0], level, "{k} of 16");
        }
    }
}
