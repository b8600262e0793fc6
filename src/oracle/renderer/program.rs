//! Another renderer as an external program (the `hunt` protocol): the scene written to a
//! file, the program run with a timeout, its output file read as [`Theirs`]. A non-zero
//! exit, a crash, a timeout, no output or unreadable output is a [`RenderFailure`], a finding in
//! its own right.
//!
//! On unix the program runs in a process group of its own (`setpgid(0, 0)`, std's
//! `CommandExt::process_group`), and the whole group is killed (`killpg(2)`, SIGKILL) when
//! it times out, when it has exited (whatever it left running in the background), and on
//! [`ProcessGroups::kill_all`], which `rasterproof hunt`'s Ctrl-C handler calls: no child
//! of the renderer outlives it. (Being in its own group, the renderer does not get the
//! terminal's Ctrl-C itself.)

use std::fmt;
use std::io::Read as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use crate::oracle::theirs::{Background, Format, Theirs};
use crate::scene::Scene;

/// Another renderer as `hunt`, its convention fit and its shrinker call it: scene in,
/// their output (or how it failed) out. A closure is one (a renderer driven from Rust), a
/// per-scene [`Program`] is one, a stay-alive program (`stay_alive::StayAlive`) is one.
pub trait Renderer: Sync {
    /// Their output for `scene`.
    ///
    /// # Errors
    /// How the renderer failed on it (a finding).
    fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure>;

    /// How many scenes it was asked to render and how many programs it started for them
    /// (`None` for a renderer that is not a program).
    fn runs(&self) -> Option<RendererRuns> {
        None
    }

    /// For a program: the folder of its temporary files and its process groups (what a
    /// Ctrl-C handler removes and kills); `None` otherwise.
    fn files_and_groups(&self) -> Option<(&Path, ProcessGroups)> {
        None
    }
}

/// What a hunt cost the renderer: scenes asked for, programs started.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RendererRuns {
    /// Scenes it was asked to render (the hunt's cases, its shrinking, its fit).
    pub calls: u64,
    /// Programs started: one per call for a per-scene program; one per job, plus one after
    /// each failure, for a stay-alive one.
    pub starts: u64,
}

impl<F> Renderer for F
where
    F: Fn(&Scene) -> Result<Theirs, RenderFailure> + Sync,
{
    fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure> {
        self(scene)
    }
}

impl Renderer for Program {
    fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure> {
        Program::render(self, scene)
    }

    fn runs(&self) -> Option<RendererRuns> {
        let calls = self.count.load(Ordering::Relaxed);
        Some(RendererRuns { calls, starts: calls })
    }

    fn files_and_groups(&self) -> Option<(&Path, ProcessGroups)> {
        Some((self.temp_dir(), self.process_groups()))
    }
}

/// How an external renderer failed on a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FailureKind {
    /// It exited with a non-zero status.
    Exit,
    /// It was killed by a signal (a crash).
    Crash,
    /// It ran past the timeout and was killed.
    Timeout,
    /// It exited 0 but wrote no output file.
    NoOutput,
    /// Its output file is not what `--as` says, or not the scene's size.
    BadOutput,
    /// A stay-alive renderer broke the protocol: a malformed, oversized, unasked-for or
    /// out-of-turn response line (the stay-alive protocol).
    Protocol,
}

impl FailureKind {
    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            FailureKind::Exit => "non-zero exit",
            FailureKind::Crash => "crash",
            FailureKind::Timeout => "timeout",
            FailureKind::NoOutput => "no output",
            FailureKind::BadOutput => "unreadable output",
            FailureKind::Protocol => "protocol error",
        }
    }
}

/// A failure, with what the program said.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RenderFailure {
    /// What happened.
    pub kind: FailureKind,
    /// The details: exit status, the end of its stderr, the reader's error.
    pub message: String,
}

impl fmt::Display for RenderFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.kind.name(), self.message)
    }
}

/// A folder of temporaries, removed with everything in it when dropped.
#[derive(Debug)]
pub(super) struct TempDir(pub(super) PathBuf);

impl TempDir {
    /// A fresh folder `rasterproof-WHAT-PID-N` under the system temp dir.
    pub(super) fn new(what: &str) -> Result<TempDir, String> {
        static DIRS: AtomicU64 = AtomicU64::new(0);
        let dir = std::env::temp_dir().join(format!(
            "rasterproof-{what}-{}-{}",
            std::process::id(),
            DIRS.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
        Ok(TempDir(dir))
    }
}

/// `cmd` (the value of the option `flag`) split as a POSIX shell splits words: not
/// empty, holding each of `placeholders`, its program found.
pub(super) fn command_words(cmd: &str, flag: &str, placeholders: &[&str]) -> Result<Vec<String>, String> {
    let argv = shell_words::split(cmd).map_err(|e| format!("{flag}: cannot split {cmd:?}: {e}"))?;
    let Some(program) = argv.first() else {
        return Err(format!("{flag}: empty"));
    };
    for placeholder in placeholders {
        if !argv.iter().any(|a| a.contains(placeholder)) {
            return Err(format!("{flag}: {cmd:?} has no {placeholder} placeholder"));
        }
    }
    if !program_exists(program) {
        return Err(format!("{flag}: program {program:?} not found"));
    }
    Ok(argv)
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The process groups of the renderers running now (one per [`Program::render`] in
/// flight), shared between a [`Program`] and whoever must stop them from outside, such as
/// a Ctrl-C handler: [`ProcessGroups::kill_all`]. Cloning shares the set.
#[derive(Debug, Clone, Default)]
pub struct ProcessGroups(Arc<Mutex<Groups>>);

/// The set behind [`ProcessGroups`]: the live groups, and whether `kill_all` was called
/// (a renderer started after it is killed at once: the process is ending).
#[derive(Debug, Default)]
struct Groups {
    live: Vec<u32>,
    closed: bool,
}

impl ProcessGroups {
    /// Kills every process of every group in the set (SIGKILL), and every renderer
    /// started after it as soon as it starts (the caller is ending the process); a no-op
    /// off unix. The renderers' own [`Program::render`] calls then see them killed.
    pub fn kill_all(&self) {
        let mut groups = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        groups.closed = true;
        for &group in &groups.live {
            kill_group(group);
        }
    }

    pub(super) fn add(&self, group: u32) {
        let mut groups = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        groups.live.push(group);
        if groups.closed {
            kill_group(group);
        }
    }

    pub(super) fn remove(&self, group: u32) {
        let mut groups = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        groups.live.retain(|&g| g != group);
    }
}

/// Sends SIGKILL to process group `group` (its leader's pid); errors (the group is gone
/// already) are ignored. A no-op off unix, where only the program itself is killed.
pub(super) fn kill_group(group: u32) {
    #[cfg(unix)]
    {
        use nix::sys::signal::{killpg, Signal};
        use nix::unistd::Pid;
        if let Ok(pid) = i32::try_from(group) {
            if pid > 1 {
                let _ = killpg(Pid::from_raw(pid), Signal::SIGKILL);
            }
        }
    }
    #[cfg(not(unix))]
    let _ = group;
}

/// A started renderer and its process group: dropping it kills the group (if the leader
/// is not reaped yet, the leader too), reaps the leader and forgets the group, whichever
/// way `Program::run` leaves (a result, an error, a panic).
struct Running<'a> {
    child: std::process::Child,
    groups: &'a ProcessGroups,
    reaped: bool,
}

impl Drop for Running<'_> {
    fn drop(&mut self) {
        let group = self.child.id();
        // While the leader is not reaped its pid, and so the group's id, cannot be reused:
        // the kill reaches this group only. After a reap (a normal exit) the id is still
        // held while any member of the group lives, which is when the kill matters.
        kill_group(group);
        if !self.reaped {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
        self.groups.remove(group);
    }
}

/// An external renderer: `PROGRAM ARGS...` with `{scene}` and `{out}` replaced by paths.
#[derive(Debug)]
pub struct Program {
    argv: Vec<String>,
    format: Format,
    background: Background,
    timeout: Duration,
    dir: TempDir,
    count: AtomicU64,
    groups: ProcessGroups,
}

/// How much of a failing program's stderr a failure keeps (its end).
const STDERR_KEPT: usize = 600;

impl Program {
    /// The renderer `cmd` (split as a POSIX shell splits words, run without a shell),
    /// whose output is read as `format`, killed after `timeout`.
    ///
    /// # Errors
    /// `cmd` is empty, does not parse, lacks `{scene}` or `{out}`, its program cannot be
    /// found, or the temporary folder cannot be made: one line naming the problem.
    pub fn new(cmd: &str, format: Format, background: Background, timeout: Duration) -> Result<Program, String> {
        Ok(Program {
            argv: command_words(cmd, "--cmd", &["{scene}", "{out}"])?,
            format,
            background,
            timeout,
            dir: TempDir::new("hunt")?,
            count: AtomicU64::new(0),
            groups: ProcessGroups::default(),
        })
    }

    /// The folder its scene and output files are written in (removed when the program is
    /// dropped; a caller that ends the process on a signal removes it itself).
    pub fn temp_dir(&self) -> &std::path::Path {
        &self.dir.0
    }

    /// The process groups of its runs in flight: [`ProcessGroups::kill_all`] kills them
    /// all (what a Ctrl-C handler calls before it ends the process).
    pub fn process_groups(&self) -> ProcessGroups {
        self.groups.clone()
    }

    /// The format its output is read as.
    pub fn format(&self) -> Format {
        self.format
    }

    /// Runs the program on `scene` and reads its output. Its files are removed afterwards.
    ///
    /// # Errors
    /// A [`RenderFailure`]: the program failed, or its output is unreadable.
    pub fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure> {
        let n = self.count.fetch_add(1, Ordering::Relaxed);
        let scene_path = self.dir.0.join(format!("scene-{n}.json"));
        let ext = match self.format {
            Format::Json => "json",
            Format::Values => "tiff",
            _ => "png",
        };
        let out_path = self.dir.0.join(format!("out-{n}.{ext}"));
        let err_path = self.dir.0.join(format!("stderr-{n}.txt"));
        let result = self.run(scene, &scene_path, &out_path, &err_path);
        for p in [&scene_path, &out_path, &err_path] {
            let _ = std::fs::remove_file(p);
        }
        result
    }

    fn run(&self, scene: &Scene, scene_path: &Path, out_path: &Path, err_path: &Path) -> Result<Theirs, RenderFailure> {
        let fail = |kind, message: String| RenderFailure { kind, message };
        std::fs::write(scene_path, scene.to_json())
            .map_err(|e| fail(FailureKind::BadOutput, format!("cannot write the scene: {e}")))?;
        let fill = |a: &String| {
            a.replace("{scene}", &scene_path.to_string_lossy())
                .replace("{out}", &out_path.to_string_lossy())
        };
        let args: Vec<String> = self.argv[1..].iter().map(fill).collect();
        let stderr = std::fs::File::create(err_path)
            .map_err(|e| fail(FailureKind::BadOutput, format!("cannot capture stderr: {e}")))?;
        let mut command = Command::new(&self.argv[0]);
        command
            .args(&args)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(stderr);
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut command, 0);
        let child = command
            .spawn()
            .map_err(|e| fail(FailureKind::Exit, format!("cannot start {:?}: {e}", self.argv[0])))?;
        self.groups.add(child.id());
        let mut running = Running {
            child,
            groups: &self.groups,
            reaped: false,
        };
        let deadline = Instant::now() + self.timeout;
        let status = loop {
            match running.child.try_wait() {
                Ok(Some(status)) => {
                    running.reaped = true;
                    break status;
                }
                Ok(None) if Instant::now() >= deadline => {
                    drop(running);
                    return Err(fail(
                        FailureKind::Timeout,
                        format!("killed after {} s", self.timeout.as_secs_f64()),
                    ));
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(2)),
                Err(e) => return Err(fail(FailureKind::Exit, format!("cannot wait for it: {e}"))),
            }
        };
        // Kill what it left running in the background.
        drop(running);
        let said = stderr_tail(err_path);
        if !status.success() {
            #[cfg(unix)]
            {
                use std::os::unix::process::ExitStatusExt as _;
                if let Some(signal) = status.signal() {
                    return Err(fail(FailureKind::Crash, format!("killed by signal {signal}{said}")));
                }
            }
            return Err(fail(FailureKind::Exit, format!("{status}{said}")));
        }
        read_output(out_path, self.format, self.background, scene, &said)
    }
}

/// Their output file for `scene`, read as `format`: no file, an unreadable one or one of
/// another size is a [`RenderFailure`] (`said`: the end of their stderr, or nothing).
pub(super) fn read_output(
    out_path: &Path,
    format: Format,
    background: Background,
    scene: &Scene,
    said: &str,
) -> Result<Theirs, RenderFailure> {
    let fail = |kind, message: String| RenderFailure { kind, message };
    let Ok(bytes) = std::fs::read(out_path) else {
        return Err(fail(FailureKind::NoOutput, format!("it wrote no {}{said}", "{out}")));
    };
    let theirs =
        Theirs::read(&bytes, "{out}", format, background).map_err(|e| fail(FailureKind::BadOutput, e.message))?;
    // Under a pattern of several samples the image is one per sample index, stacked.
    let samples = scene
        .samples
        .as_ref()
        .filter(|p| scene.target().is_ok_and(|t| !p.is_single(&t.convention)))
        .map_or(1, |p| u32::try_from(p.len()).unwrap_or(u32::MAX));
    let height = scene.height.saturating_mul(samples);
    if (theirs.width(), theirs.height()) != (scene.width, height) {
        let stacked = if samples > 1 {
            format!(" ({samples} sample images of {}x{} stacked)", scene.width, scene.height)
        } else {
            String::new()
        };
        return Err(fail(
            FailureKind::BadOutput,
            format!(
                "its image is {}x{}, the scene's canvas {}x{height}{stacked}",
                theirs.width(),
                theirs.height(),
                scene.width,
            ),
        ));
    }
    Ok(theirs)
}

/// `; stderr: ...` with the end of the captured stderr, or nothing when it is empty.
pub(super) fn stderr_tail(path: &Path) -> String {
    let mut text = String::new();
    if let Ok(mut f) = std::fs::File::open(path) {
        let _ = f.read_to_string(&mut text);
    }
    let text = text.trim();
    if text.is_empty() {
        return String::new();
    }
    let start = text.char_indices().rev().nth(STDERR_KEPT).map_or(0, |(k, _)| k);
    format!("; stderr: {}", &text[start..])
}

/// Whether `program` names a file, or a file on `PATH`.
fn program_exists(program: &str) -> bool {
    let p = Path::new(program);
    if p.components().count() > 1 {
        return p.is_file();
    }
    std::env::var_os("PATH").is_some_and(|path| std::env::split_paths(&path).any(|d| d.join(program).is_file()))
}
