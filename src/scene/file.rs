//! A scene file read from disk: [`read_scene_file`], its size checked before reading, a big
//! file read on several threads, then parsed ([`super::parse_scene_with`]).

use std::path::Path;

use super::parse::{parse_scene_with, ParseOptions, MAX_SCENE_BYTES};
use super::{Scene, SceneError};

/// Reads and parses the scene file at `path` as `options` ask (a big file read and its
/// triangles parsed on up to `options.jobs` threads), named in errors as
/// the path is written. A file over [`MAX_SCENE_BYTES`] is refused before it is read, so
/// that a huge file costs nothing.
///
/// # Errors
/// The file is too big or cannot be read, or it is not a valid scene: a [`SceneError`]
/// naming the file (and the field and value where one is at fault).
pub fn read_scene_file(path: &Path, options: &ParseOptions) -> Result<Scene, SceneError> {
    let name = path.display().to_string();
    let whole = |message: String| SceneError {
        source: name.clone(),
        field: String::new(),
        message,
    };
    if let Ok(m) = std::fs::metadata(path) {
        if m.len() > MAX_SCENE_BYTES as u64 {
            return Err(whole(format!(
                "{} bytes, at most {MAX_SCENE_BYTES} (1 GiB) per scene file",
                m.len()
            )));
        }
    }
    let bytes = read_file(path, options.jobs).map_err(|e| whole(format!("cannot read: {e}")))?;
    parse_scene_with(&bytes, &name, options)
}

/// A file's bytes; a big regular file on `jobs` threads, each reading its part of one
/// buffer at its offset (the copies and the fresh memory they touch are most of the
/// time of reading a cached file), then checked to end where its size said. Anything
/// else (one job, a small file, a pipe, a file that changed size) is read as one stream.
fn read_file(path: &Path, jobs: usize) -> std::io::Result<Vec<u8>> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileExt;
        const BIG: u64 = 8 << 20;
        let file = std::fs::File::open(path)?;
        let meta = file.metadata()?;
        if jobs > 1 && meta.is_file() && meta.len() >= BIG {
            let len = usize::try_from(meta.len()).map_err(std::io::Error::other)?;
            let mut bytes = vec![0u8; len];
            let part = len.div_ceil(jobs);
            let parts: Vec<(usize, &mut [u8])> = bytes.chunks_mut(part).enumerate().collect();
            let read: std::io::Result<()> =
                crate::chunks::map_each(parts, jobs, |(k, chunk)| file.read_exact_at(chunk, (k * part) as u64))
                    .into_iter()
                    .collect();
            if read.is_ok() && file.read_at(&mut [0u8; 1], meta.len())? == 0 {
                return Ok(bytes);
            }
        }
    }
    std::fs::read(path)
}
