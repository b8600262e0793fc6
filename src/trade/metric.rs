//! One measured error ([`Metric`]): a rate of events, or a distribution in ulps, f32 steps
//! or quanta; each kind knows its own unit. Shared by the measurements (`measure`, the
//! families) that build metrics and by the report that prints them, so that neither
//! imports the other.

/// One measured error.
#[derive(Debug, Clone, PartialEq)]
pub enum Metric {
    /// `count` events out of `of` opportunities (wrong pixels of the covered pixels, ...).
    Rate {
        /// What is counted (`wrong pixels`, `gaps`, ...).
        name: &'static str,
        /// How many.
        count: u64,
        /// Out of how many.
        of: u64,
    },
    /// A distribution in ulps (barycentric sums).
    Ulps {
        /// What is measured.
        name: &'static str,
        /// The median.
        median: f64,
        /// The largest.
        max: f64,
        /// How many samples.
        samples: u64,
    },
    /// The tail of a distribution of distances in f32 steps (units in the last place):
    /// interpolated values, each the count of f32 values from the exact value's nearest f32
    /// to the model's (0: the model gave the correctly rounded value).
    UlpTail {
        /// What is measured.
        name: &'static str,
        /// The 99th percentile (the smallest distance at least 99 % of the values are
        /// within).
        p99: f64,
        /// The largest.
        max: f64,
        /// How many values.
        samples: u64,
    },
    /// A distribution of absolute coverage errors, in quanta of 1/255 (area coverage).
    Quanta {
        /// What is measured.
        name: &'static str,
        /// The largest error (0 exactly when every pixel is exact).
        max: f64,
        /// The mean error over `pixels`.
        mean: f64,
        /// The pixels measured: those where the exact value or the model's is not zero.
        pixels: u64,
    },
}

impl Metric {
    /// The metric's name.
    pub fn name(&self) -> &'static str {
        match self {
            Metric::Rate { name, .. }
            | Metric::Ulps { name, .. }
            | Metric::UlpTail { name, .. }
            | Metric::Quanta { name, .. } => name,
        }
    }

    /// The unit its [cells](Metric::cell) are written in, as a table's header says it:
    /// `per million` for a rate, `ulps median/max` for a distribution in ulps,
    /// `ulps p99/max` for the tail of f32 steps, `1/255 max/mean` for coverage errors in
    /// quanta.
    ///
    /// ```
    /// use rasterproof::trade::Metric;
    /// assert_eq!(Metric::Rate { name: "gaps", count: 1, of: 4 }.unit(), "per million");
    /// let ulps = Metric::Ulps { name: "sum", median: 0.5, max: 1.0, samples: 3 };
    /// assert_eq!(ulps.unit(), "ulps median/max");
    /// let q = Metric::Quanta { name: "coverage error", max: 1.5, mean: 0.25, pixels: 9 };
    /// assert_eq!((q.unit(), q.cell().as_str()), ("1/255 max/mean", "1.5/0.25"));
    /// let tail = Metric::UlpTail { name: "ulps", p99: 2.0, max: 130.0, samples: 9 };
    /// assert_eq!((tail.unit(), tail.cell().as_str()), ("ulps p99/max", "2/130"));
    /// ```
    pub fn unit(&self) -> &'static str {
        match self {
            Metric::Rate { .. } => "per million",
            Metric::Ulps { .. } => "ulps median/max",
            Metric::UlpTail { .. } => "ulps p99/max",
            Metric::Quanta { .. } => "1/255 max/mean",
        }
    }

    /// Whether it shows no error at all.
    pub fn is_zero(&self) -> bool {
        match self {
            Metric::Rate { count, .. } => *count == 0,
            Metric::Ulps { max, .. } | Metric::UlpTail { max, .. } | Metric::Quanta { max, .. } => *max == 0.0,
        }
    }

    /// A rate per million opportunities (`None` for ulps, or nothing to count).
    pub fn per_million(&self) -> Option<f64> {
        match self {
            Metric::Rate { count, of, .. } if *of > 0 => Some(ratio(*count, *of) * 1e6),
            _ => None,
        }
    }

    /// A short cell: `123.4` per million (`0` exactly), `median/max` ulps, `p99/max` f32
    /// steps, or `max/mean` quanta.
    pub fn cell(&self) -> String {
        match self {
            Metric::Rate { count: 0, .. } => "0".into(),
            Metric::Rate { .. } => self.per_million().map_or_else(|| "-".into(), short),
            Metric::Ulps {
                median, max, samples, ..
            } => format!("{}/{} (n={samples})", short(*median), short(*max)),
            Metric::UlpTail { p99, max, .. } => format!("{}/{}", short(*p99), short(*max)),
            Metric::Quanta { max, mean, .. } => format!("{}/{}", short(*max), short(*mean)),
        }
    }
}

/// `a / b` as f64 (both far below 2^53 here).
#[allow(clippy::cast_precision_loss)] // counts below 2^53
fn ratio(a: u64, b: u64) -> f64 {
    a as f64 / b as f64
}

/// A number as a person reads it in a column: always in decimal notation (no exponent,
/// so that the cells of one column compare at a glance), whole from 100 up, with up to
/// three decimals from 1 to 100, and with two significant digits below 1.
///
/// ```text
/// 0 -> "0"   0.0512 -> "0.051"   0.000123 -> "0.00012"   2.5 -> "2.5"   257000000 -> "257000000"
/// ```
pub(crate) fn short(v: f64) -> String {
    let trim = |s: String| s.trim_end_matches('0').trim_end_matches('.').to_string();
    if v == 0.0 {
        "0".into()
    } else if !v.is_finite() || v.abs() >= 100.0 {
        format!("{v:.0}")
    } else if v.abs() >= 1.0 {
        trim(format!("{v:.3}"))
    } else {
        // Two significant digits: the first non-zero decimal and the next.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)] // 1 <= digits <= 325
        let digits = (1.0 - v.abs().log10().floor()) as usize;
        trim(format!("{v:.digits$}"))
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    /// One notation in a column: decimals, never an exponent (hand-written values).
    #[test]
    fn numbers_are_written_in_decimal_notation() {
        let cases = [
            (0.0, "0"),
            (0.0512, "0.051"),
            (0.000_123, "0.00012"),
            (0.1, "0.1"),
            (0.099, "0.099"),
            (0.95, "0.95"),
            (2.5, "2.5"),
            (12.345_6, "12.346"),
            (194.4, "194"),
            (161_000.0, "161000"),
            (257_000_000.0, "257000000"),
        ];
        for (v, text) in cases {
            assert_eq!(short(v), text, "{v}");
        }
    }
}
