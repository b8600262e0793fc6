//! Shards: a deterministic partition of a run's cases, so that N machines run disjoint
//! cases and together exactly the cases of the unsharded run (`check --shard K/N`).
//!
//! Shard K of N (written `K/N`, `1 <= K <= N`) holds the cases `k` of `0..cases` with
//! `k mod N == K - 1`: case 0 is in shard 1, case 1 in shard 2, ..., case N in shard 1
//! again. The partition depends only on the case index, not on how long cases take or on
//! the number of threads, and every case is in exactly one shard of N.

use std::collections::BTreeSet;
use std::fmt;
use std::str::FromStr;

/// One shard: `K/N`, the cases `k` with `k mod N == K - 1`.
///
/// # Guarantees
/// `1 <= index <= count`.
///
/// ```
/// use rasterproof::harness::suite::Shard;
/// let s: Shard = "2/3".parse().unwrap();
/// assert_eq!((s.index(), s.count()), (2, 3));
/// assert_eq!(s.cases(8).collect::<Vec<_>>(), [1, 4, 7]);
/// assert_eq!(s.case_count(8), 3);
/// assert!("0/3".parse::<Shard>().is_err() && "4/3".parse::<Shard>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Shard {
    index: u64,
    count: u64,
}

impl Shard {
    /// The whole run: shard 1 of 1.
    pub const WHOLE: Shard = Shard { index: 1, count: 1 };

    /// Shard `index` of `count`.
    ///
    /// # Errors
    /// `count` is 0, or `index` is not in `1..=count`: the reason, naming the values.
    pub fn new(index: u64, count: u64) -> Result<Shard, String> {
        if count == 0 {
            return Err(format!(
                "{index}/{count}: N must be at least 1 (K/N: shard K of N, 1 <= K <= N)"
            ));
        }
        if index == 0 || index > count {
            return Err(format!(
                "{index}/{count}: K must be in 1..={count} (K/N: shard K of N, 1 <= K <= N)"
            ));
        }
        Ok(Shard { index, count })
    }

    /// K: which shard, from 1.
    pub fn index(self) -> u64 {
        self.index
    }

    /// N: how many shards.
    pub fn count(self) -> u64 {
        self.count
    }

    /// Whether case `k` belongs to this shard.
    pub fn contains(self, k: u64) -> bool {
        k % self.count == self.index - 1
    }

    /// The number of this shard's cases among `0..total`.
    pub fn case_count(self, total: u64) -> u64 {
        let first = self.index - 1;
        if total <= first {
            0
        } else {
            (total - first - 1) / self.count + 1
        }
    }

    /// The `j`-th case of this shard (from 0), whatever the total: `K - 1 + j N`; `None`
    /// past `u64::MAX`.
    pub fn case_at(self, j: u64) -> Option<u64> {
        j.checked_mul(self.count)?.checked_add(self.index - 1)
    }

    /// This shard's cases among `0..total`, ascending.
    pub fn cases(self, total: u64) -> impl Iterator<Item = u64> {
        (0..self.case_count(total)).filter_map(move |j| self.case_at(j))
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// `K/N`, as `--shard` takes it.
impl FromStr for Shard {
    type Err = String;

    fn from_str(s: &str) -> Result<Shard, String> {
        let expected = || format!("{s:?}: expected K/N (shard K of N, 1 <= K <= N), e.g. 2/3");
        let (k, n) = s.split_once('/').ok_or_else(expected)?;
        let number = |t: &str| t.trim().parse::<u64>().map_err(|_| expected());
        Shard::new(number(k)?, number(n)?)
    }
}

/// The shards of N a report holds: one for a shard's run, several after a merge.
///
/// # Guarantees
/// `count >= 1`; `indices` is not empty and each is in `1..=count`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Shards {
    count: u64,
    indices: BTreeSet<u64>,
}

impl Shards {
    /// The shards `indices` of `count`.
    ///
    /// # Errors
    /// `count` is 0, `indices` is empty, or an index is not in `1..=count`.
    pub fn new(count: u64, indices: impl IntoIterator<Item = u64>) -> Result<Shards, String> {
        let indices: BTreeSet<u64> = indices.into_iter().collect();
        if indices.is_empty() {
            return Err("no shard".to_string());
        }
        for &k in &indices {
            Shard::new(k, count)?;
        }
        Ok(Shards { count, indices })
    }

    /// N.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// The Ks, ascending.
    pub fn indices(&self) -> impl Iterator<Item = u64> + '_ {
        self.indices.iter().copied()
    }

    /// Whether these are all the cases: every shard of N (1/1 included).
    pub fn is_whole(&self) -> bool {
        u64::try_from(self.indices.len()) == Ok(self.count)
    }

    /// Whether case `k` is in one of these shards.
    pub fn contains(&self, k: u64) -> bool {
        self.indices.contains(&(k % self.count + 1))
    }

    /// The number of their cases among `0..total`.
    pub fn case_count(&self, total: u64) -> u64 {
        self.indices
            .iter()
            .map(|&k| {
                Shard {
                    index: k,
                    count: self.count,
                }
                .case_count(total)
            })
            .sum()
    }

    /// The shards both hold, ascending (empty when they are disjoint or of different N).
    pub fn overlap(&self, other: &Shards) -> Vec<u64> {
        if self.count != other.count {
            return Vec::new();
        }
        self.indices.intersection(&other.indices).copied().collect()
    }

    /// Both sets together (same N, disjoint: see [`Shards::overlap`]).
    pub(super) fn union(&self, other: &Shards) -> Shards {
        let indices: BTreeSet<u64> = self.indices.union(&other.indices).copied().collect();
        Shards {
            count: self.count,
            indices,
        }
    }

    /// These shards written as a whole run (1/1) when they are every shard of N.
    pub(super) fn normalised(self) -> Shards {
        if self.is_whole() {
            Shard::WHOLE.into()
        } else {
            self
        }
    }
}

impl From<Shard> for Shards {
    fn from(s: Shard) -> Shards {
        Shards {
            count: s.count,
            indices: BTreeSet::from([s.index]),
        }
    }
}

/// `K/N`, or `K1,K2/N` for several.
impl fmt::Display for Shards {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ks: Vec<String> = self.indices.iter().map(u64::to_string).collect();
        write!(f, "{}/{}", ks.join(","), self.count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_of_n_partition_the_cases() {
        for n in 1..=5 {
            let mut seen = vec![0u32; 23];
            for k in 1..=n {
                let s = Shard::new(k, n).unwrap();
                assert_eq!(s.cases(23).count() as u64, s.case_count(23));
                for c in s.cases(23) {
                    assert!(s.contains(c));
                    seen[usize::try_from(c).unwrap()] += 1;
                }
            }
            assert!(seen.iter().all(|&m| m == 1), "{n}: {seen:?}");
        }
        assert_eq!(Shard::new(5, 5).unwrap().case_count(3), 0);
        assert_eq!(Shard::WHOLE.cases(3).collect::<Vec<_>>(), [0, 1, 2]);
    }

    #[test]
    fn bad_shards_are_refused_naming_the_value() {
        for (text, part) in [
            ("0/0", "N must be at least 1"),
            ("4/3", "K must be in 1..=3"),
            ("0/3", "K must be in 1..=3"),
            ("x", "expected K/N"),
            ("1/", "expected K/N"),
            ("-1/3", "expected K/N"),
        ] {
            let e = text.parse::<Shard>().unwrap_err();
            assert!(e.contains(part) && e.contains(text.trim_matches('"')), "{text}: {e}");
        }
    }

    #[test]
    fn shard_sets_overlap_union_and_whole() {
        let a = Shards::new(3, [1, 3]).unwrap();
        let b: Shards = Shard::new(2, 3).unwrap().into();
        assert_eq!(a.overlap(&b), Vec::<u64>::new());
        assert_eq!(a.overlap(&Shards::new(3, [3]).unwrap()), [3]);
        assert_eq!(a.to_string(), "1,3/3");
        assert_eq!(a.case_count(10), 4 + 3);
        let all = a.union(&b);
        assert!(all.is_whole());
        assert_eq!(all.normalised(), Shard::WHOLE.into());
        assert!(Shards::new(3, [4]).is_err() && Shards::new(3, []).is_err());
    }
}
