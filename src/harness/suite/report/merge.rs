//! Merging the reports of disjoint shards of one run into the report of their cases
//! together ([`SuiteReport::merge`]): the report of the whole run once every shard is in.

use std::collections::BTreeMap;

use super::SuiteReport;

impl SuiteReport {
    /// Merges the reports of disjoint shards of one run (each with the name of its file,
    /// for the errors) into the report of their cases together: the report of the whole
    /// run once every shard is in. The order of the reports does not matter.
    ///
    /// # Errors
    /// No report; two reports of different versions of rasterproof, seeds, case counts or
    /// shard counts; two reports holding the same shard: one line naming both files.
    pub fn merge(reports: impl IntoIterator<Item = (String, SuiteReport)>) -> Result<SuiteReport, String> {
        let mut parts: Vec<(String, SuiteReport)> = reports.into_iter().collect();
        parts.sort_by_key(|(_, r)| r.shards.indices().next());
        let mut parts = parts.into_iter();
        let (first_name, mut merged) = parts.next().ok_or("no report to merge")?;
        let mut holder: BTreeMap<u64, String> = merged.shards.indices().map(|k| (k, first_name.clone())).collect();
        for (name, r) in parts {
            let a = &first_name;
            if r.rasterproof != merged.rasterproof {
                return Err(format!(
                    "{a} and {name}: written by different versions of rasterproof ({} and {}): their cases differ",
                    merged.rasterproof, r.rasterproof
                ));
            }
            if r.seed != merged.seed {
                return Err(format!(
                    "{a} and {name}: different seeds ({} and {}): not shards of one run",
                    merged.seed, r.seed
                ));
            }
            if r.cases != merged.cases {
                return Err(format!(
                    "{a} and {name}: different case counts (--cases {} and {}): not shards of one run",
                    merged.cases, r.cases
                ));
            }
            if r.shards.count() != merged.shards.count() {
                return Err(format!(
                    "{a} and {name}: shards of different counts ({} and {}): not shards of one partition",
                    merged.shards, r.shards
                ));
            }
            if let Some(&k) = merged.shards.overlap(&r.shards).first() {
                return Err(format!(
                    "{} and {name}: both hold shard {k}/{}: the same cases twice",
                    holder[&k],
                    r.shards.count()
                ));
            }
            holder.extend(r.shards.indices().map(|k| (k, name.clone())));
            merged.absorb(r);
        }
        if merged.is_complete() {
            merged.shards = merged.shards.normalised();
        }
        Ok(merged)
    }

    /// Adds `other`'s cases (disjoint shards of the same run) to this report's.
    fn absorb(&mut self, other: SuiteReport) {
        self.shards = self.shards.union(&other.shards);
        self.stopped.extend(other.stopped);
        for (family, n) in other.families {
            *self.families.entry(family).or_default() += n;
        }
        self.tally.merge(&other.tally);
        self.failures.extend(other.failures);
        self.failures.sort_by_key(|f| f.case);
    }
}
