//! One measured error ([`Metric`]): a rate of events, or a distribution in ulps; each
//! kind knows its own unit. Shared by the measurements (`measure`, the families) that
//! build metrics and by the report that prints them, so that neither imports the other.

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
}

impl Metric {
    /// The metric's name.
    pub fn name(&self) -> &'static str {
        match self {
            Metric::Rate { name, .. } | Metric::Ulps { name, .. } => name,
        }
    }

    /// The unit its [cells](Metric::cell) are written in, as a table's header says it:
    /// `per million` for a rate, `ulps median/max` for a distribution in ulps.
    ///
    /// ```
    /// use rasterproof::trade::Metric;
    /// assert_eq!(Metric::Rate { name: "gaps", count: 1, of: 4 }.unit(), "per million");
    /// let ulps = Metric::Ulps { name: "sum", median: 0.5, max: 1.0, samples: 3 };
    /// assert_eq!(ulps.unit(), "ulps median/max");
    /// ```
    pub fn unit(&self) -> &'static str {
        match self {
            Metric::Rate { .. } => "per million",
            Metric::Ulps { .. } => "ulps median/max",
        }
    }

    /// Whether it shows no error at all.
    pub fn is_zero(&self) -> bool {
        match self {
            Metric::Rate { count, .. } => *count == 0,
            Metric::Ulps { max, .. } => *max == 0.0,
        }
    }

    /// A rate per million opportunities (`None` for ulps, or nothing to count).
    pub fn per_million(&self) -> Option<f64> {
        match self {
            Metric::Rate { count, of, .. } if *of > 0 => Some(ratio(*count, *of) * 1e6),
            _ => None,
        }
    }

    /// A short cell: `123.4` per million (`0` exactly), or `median/max` ulps.
    pub fn cell(&self) -> String {
        match self {
            Metric::Rate { count: 0, .. } => "0".into(),
            Metric::Rate { .. } => self.per_million().map_or_else(|| "-".into(), short),
            Metric::Ulps {
                median, max, samples, ..
            } => format!("{}/{} (n={samples})", short(*median), short(*max)),
        }
    }
}

/// `a / b` as f64 (both far below 2^53 here).
#[allow(clippy::cast_precision_loss)] // counts below 2^53
fn ratio(a: u64, b: u64) -> f64 {
    a as f64 / b as f64
}

/// A number in 4 significant digits at most, no exponent below 10^7.
pub(crate) fn short(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if v.abs() >= 1e7 {
        format!("{v:.2e}")
    } else if v.abs() >= 100.0 {
        format!("{v:.0}")
    } else if v.abs() >= 1.0 {
        format!("{v:.3}").trim_end_matches('0').trim_end_matches('.').into()
    } else {
        format!("{v:.2e}")
    }
}
