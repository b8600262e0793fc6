//! The check report reader (`harness::suite::SuiteReport::from_json`, what `check-merge`
//! reads) on arbitrary bytes: `Ok` or an error that starts with the file's name, never a
//! panic. A report it accepts is whole: it writes back (`to_json`) to a file that reads as
//! the same report, its table (`lines`) and JUnit XML are written without panicking, it
//! merges alone into itself (normalised when complete), and merging it with itself is
//! refused (the same shard twice).
//!
//! `Debug` is the bytes; seeds are reports `rasterproof check --report` wrote (whole,
//! sharded, interrupted, with failures).

#![no_main]

use libfuzzer_sys::fuzz_target;
use rasterproof::harness::suite::SuiteReport;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let report = match SuiteReport::from_json(text, "report.json") {
        Ok(r) => r,
        Err(e) => {
            assert!(
                e.starts_with("report.json: "),
                "an error that does not name the file: {e}"
            );
            return;
        }
    };
    let written = report.to_json();
    let again = SuiteReport::from_json(&written, "written.json")
        .unwrap_or_else(|e| panic!("a report it accepted writes a file it refuses: {e}\n{written}"));
    assert_eq!(again, report, "the written report reads back differently:\n{written}");
    let _ = report.lines();
    let _ = report.junit();
    let _ = report.findings();
    let alone = SuiteReport::merge([("a.json".to_string(), report.clone())]).expect("one report merges");
    if report.is_complete() && report.shards().is_whole() {
        // Every case of every shard of N: merged, it is written as the whole run, 1/1.
        assert_eq!(alone.shards().count(), 1, "a whole run merged alone is not 1/1");
        assert_eq!((alone.tally(), alone.failures()), (report.tally(), report.failures()));
    } else {
        assert_eq!(alone, report, "a report merged alone changed");
    }
    assert!(
        SuiteReport::merge([("a.json".to_string(), report.clone()), ("b.json".to_string(), report)]).is_err(),
        "a report merged with itself"
    );
});
