//! The machine interface of [`Coverage`]: `render --format json`, written as a stream.

use std::fmt::Write as _;

use super::Coverage;

impl Coverage {
    /// The machine interface: `{"width":W,"height":H,"pixels":[[x,y,[ids...]],...]}`,
    /// covered pixels only, sorted by y then x, ids ascending, no whitespace. The same
    /// bytes as [`Coverage::write_json`], in a string.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink};
    /// let mut c = Coverage::new(4, 3);
    /// c.cover(2, 1, 7);
    /// c.cover(0, 2, 1);
    /// c.cover(2, 1, 3);
    /// assert_eq!(c.to_json(), r#"{"width":4,"height":3,"pixels":[[2,1,[3,7]],[0,2,[1]]]}"#);
    /// ```
    pub fn to_json(&self) -> String {
        let mut bytes = Vec::new();
        self.write_json(&mut bytes).expect("writing to a Vec cannot fail");
        String::from_utf8(bytes).expect("the JSON is ASCII")
    }

    /// Writes [`Coverage::to_json`]'s text to `out` as it goes (a few tens of KiB
    /// buffered at a time), without building it in memory.
    ///
    /// ```
    /// use rasterproof::coverage::{Coverage, CoverageSink};
    /// let mut c = Coverage::new(2, 1);
    /// c.cover_span(0, 0, 1, 4);
    /// let mut out = Vec::new();
    /// c.write_json(&mut out).unwrap();
    /// assert_eq!(out, br#"{"width":2,"height":1,"pixels":[[0,0,[4]],[1,0,[4]]]}"#);
    /// ```
    ///
    /// # Errors
    /// What `out` returns.
    pub fn write_json(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        const FLUSH_AT: usize = 1 << 16;
        let mut s = format!("{{\"width\":{},\"height\":{},\"pixels\":[", self.width, self.height);
        for (n, (x, y, ids)) in self.iter().enumerate() {
            if n > 0 {
                s.push(',');
            }
            let _ = write!(s, "[{x},{y},[");
            for (k, id) in ids.iter().enumerate() {
                if k > 0 {
                    s.push(',');
                }
                let _ = write!(s, "{id}");
            }
            s.push_str("]]");
            if s.len() >= FLUSH_AT {
                out.write_all(s.as_bytes())?;
                s.clear();
            }
        }
        s.push_str("]}");
        out.write_all(s.as_bytes())
    }
}
