//! A folder under the system temp dir for one test, removed on drop. Shared by the CLI
//! tests (`crate::tempdir`, declared once in `tests/it.rs`).

#![allow(dead_code)]

/// The folder `rasterproof-test-TAG-PID`.
pub struct Dir(std::path::PathBuf);

impl Dir {
    /// Creates the folder (tags must differ between the tests of one binary).
    pub fn new(tag: &str) -> Dir {
        let p = std::env::temp_dir().join(format!("rasterproof-test-{tag}-{}", std::process::id()));
        std::fs::create_dir_all(&p).unwrap();
        Dir(p)
    }

    /// Its path.
    pub fn path(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
