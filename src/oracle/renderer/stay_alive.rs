//! Another renderer as a program that stays alive: started once, it takes scene after
//! scene, one JSON request per line on its stdin, one JSON response per line on its stdout
//! (the shape of Bazel's persistent workers, and of AFL++'s persistent mode in spirit: the
//! start-up is paid once, not per scene).
//!
//! # The protocol, version 1
//!
//! The program is started as the user wrote it (`PROGRAM ARGS`, split as a POSIX shell
//! splits words, run without a shell), in a process group of its own, with its stderr
//! kept in a file. For each scene rasterproof writes one line:
//!
//! ```text
//! {"rasterproof": 1, "id": 7, "scene": { ...the scene file's JSON... }, "out": "/tmp/.../out-7.png", "as": "ids"}
//! ```
//!
//! and the program renders the scene, writes its output to `out` exactly as a per-scene
//! program writes `{out}` (an ids or mask PNG, or the JSON coverage with `--as json`), and
//! answers one line:
//!
//! ```text
//! {"id": 7, "ok": true}
//! {"id": 7, "ok": false, "error": "what went wrong"}
//! ```
//!
//! Unknown request fields are to be ignored (later versions add them); a program that
//! cannot read a request answers `ok: false`. A response line is at most
//! [`MAX_RESPONSE_LINE`] bytes. Each request has the timeout a per-scene run has.
//!
//! Every way a program can fail is a [`RenderFailure`] of the scene it was given, never
//! a hang: `ok: false` (non-zero exit); no answer in time (timeout: its process group is
//! killed); exiting or crashing before it answers, or between requests (exit / crash, with
//! the status); a line that is not a response, that is too long, that answers another id,
//! or a line nobody asked for (protocol error); then the output file as for a per-scene
//! program (no output, unreadable output). After any failure the program's whole process
//! group is killed and the next scene starts a fresh one. Each failure carries the end of
//! its stderr.
//!
//! Several scenes run at once (`--jobs`) on as many programs: a scene takes an idle one,
//! or starts one.

use std::io::{BufRead as _, BufReader, Read as _, Write as _};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::{Mutex, PoisonError};
use std::time::Duration;

use serde_json::{json, Value};

use super::program::{
    command_words, kill_group, read_output, stderr_tail, FailureKind, ProcessGroups, RenderFailure, TempDir,
};
use super::program::{Renderer, RendererRuns};
use crate::oracle::theirs::{Background, Format, Theirs};
use crate::scene::Scene;

/// The protocol's version, sent in every request as `"rasterproof"`.
pub const PROTOCOL_VERSION: u32 = 1;

/// The longest response line read (bytes, newline included); a longer one is a protocol
/// error.
pub const MAX_RESPONSE_LINE: usize = 64 * 1024;

/// What the thread reading a program's stdout saw.
enum Said {
    /// A whole line, without its newline.
    Line(String),
    /// A line longer than [`MAX_RESPONSE_LINE`] (reading stopped there).
    TooLong,
    /// End of file (or a read error): the program closed its stdout.
    End,
}

/// One running program: its process (in a group of its own), its stdin, the lines of its
/// stdout as a reader thread sends them, and where its stderr goes. Dropping it kills the
/// group and reaps the program.
struct Worker {
    child: Child,
    stdin: Option<ChildStdin>,
    lines: Receiver<Said>,
    stderr: std::path::PathBuf,
    groups: ProcessGroups,
}

impl Drop for Worker {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let group = self.child.id();
        kill_group(group);
        let _ = self.child.kill();
        let _ = self.child.wait();
        self.groups.remove(group);
    }
}

/// A renderer that stays alive across scenes (see the module docs).
#[derive(Debug)]
pub struct StayAlive {
    argv: Vec<String>,
    format: Format,
    background: Background,
    timeout: Duration,
    dir: TempDir,
    idle: Mutex<Vec<WorkerSlot>>,
    requests: AtomicU64,
    starts: AtomicU64,
    groups: ProcessGroups,
}

/// A worker waiting in the idle list (opaque, so the list can be `Debug`).
struct WorkerSlot(Worker);

impl std::fmt::Debug for WorkerSlot {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Worker(pid {})", self.0.child.id())
    }
}

impl StayAlive {
    /// The stay-alive renderer `cmd` (split as a POSIX shell splits words, run without a
    /// shell; no placeholders: scenes come on its stdin), whose output is read as
    /// `format`, each request killed after `timeout`. Nothing is started yet.
    ///
    /// # Errors
    /// `cmd` is empty, does not parse, names a program that cannot be found, or the
    /// temporary folder cannot be made: one line naming the problem.
    pub fn new(cmd: &str, format: Format, background: Background, timeout: Duration) -> Result<StayAlive, String> {
        Ok(StayAlive {
            argv: command_words(cmd, "--serve", &[])?,
            format,
            background,
            timeout,
            dir: TempDir::new("serve")?,
            idle: Mutex::new(Vec::new()),
            requests: AtomicU64::new(0),
            starts: AtomicU64::new(0),
            groups: ProcessGroups::default(),
        })
    }

    /// The folder its output files and stderr logs are written in (removed when it is
    /// dropped).
    pub fn temp_dir(&self) -> &Path {
        &self.dir.0
    }

    /// The process groups of its programs: [`ProcessGroups::kill_all`] kills them all.
    pub fn process_groups(&self) -> ProcessGroups {
        self.groups.clone()
    }

    /// How many scenes it was asked to render.
    pub fn requests(&self) -> u64 {
        self.requests.load(Ordering::Relaxed)
    }

    /// How many times a program was started (one per job, plus one after each failure).
    pub fn starts(&self) -> u64 {
        self.starts.load(Ordering::Relaxed)
    }

    /// Renders `scene` on an idle program (or a new one) and reads its output.
    ///
    /// # Errors
    /// A [`RenderFailure`]: the program failed or broke the protocol (the module docs), or
    /// its output is unreadable. The program is then killed.
    pub fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure> {
        let n = self.requests.fetch_add(1, Ordering::Relaxed);
        let ext = if self.format == Format::Json { "json" } else { "png" };
        let out = self.dir.0.join(format!("out-{n}.{ext}"));
        let idle = self.idle.lock().unwrap_or_else(PoisonError::into_inner).pop();
        let mut worker = match idle {
            Some(WorkerSlot(w)) => w,
            None => self.start()?,
        };
        let result = self.ask(&mut worker, n, scene, &out);
        let _ = std::fs::remove_file(&out);
        if result.is_ok() {
            self.idle
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .push(WorkerSlot(worker));
        }
        result
    }

    /// Starts one program.
    fn start(&self) -> Result<Worker, RenderFailure> {
        let k = self.starts.fetch_add(1, Ordering::Relaxed);
        let fail = |message: String| RenderFailure {
            kind: FailureKind::Exit,
            message,
        };
        let stderr_path = self.dir.0.join(format!("stderr-{k}.txt"));
        let stderr = std::fs::File::create(&stderr_path).map_err(|e| fail(format!("cannot capture stderr: {e}")))?;
        let mut command = Command::new(&self.argv[0]);
        command
            .args(&self.argv[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(stderr);
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut command, 0);
        let mut child = command
            .spawn()
            .map_err(|e| fail(format!("cannot start {:?}: {e}", self.argv[0])))?;
        self.groups.add(child.id());
        let stdin = child.stdin.take();
        let stdout = child.stdout.take().expect("stdout is piped");
        let (send, lines) = mpsc::channel();
        std::thread::Builder::new()
            .name("rasterproof-serve-reader".into())
            .spawn(move || read_lines(stdout, &send))
            .map_err(|e| fail(format!("cannot start a reader thread: {e}")))?;
        Ok(Worker {
            child,
            stdin,
            lines,
            stderr: stderr_path,
            groups: self.groups.clone(),
        })
    }

    /// One request and its response on `worker`, then the output file.
    fn ask(&self, worker: &mut Worker, n: u64, scene: &Scene, out: &Path) -> Result<Theirs, RenderFailure> {
        let said = |w: &Worker| stderr_tail(&w.stderr);
        let fail = |kind, message: String| RenderFailure { kind, message };
        // Whatever it said or did since its last answer, it did between requests.
        match worker.lines.try_recv() {
            Ok(Said::Line(line)) => {
                return Err(fail(
                    FailureKind::Protocol,
                    format!(
                        "it wrote a line nobody asked for (between requests): {}{}",
                        clip(&line),
                        said(worker)
                    ),
                ))
            }
            Ok(Said::TooLong) => {
                return Err(fail(
                    FailureKind::Protocol,
                    format!(
                        "it wrote a line over {MAX_RESPONSE_LINE} bytes between requests{}",
                        said(worker)
                    ),
                ))
            }
            Ok(Said::End) => return Err(ended(worker, "between requests")),
            Err(_) => {}
        }
        let scene_json: Value = serde_json::from_str(&scene.to_json()).expect("a scene's JSON reads back");
        let request = json!({
            "rasterproof": PROTOCOL_VERSION,
            "id": n,
            "scene": scene_json,
            "out": out.to_string_lossy(),
            "as": self.format.name(),
        });
        let mut line = request.to_string();
        line.push('\n');
        let sent = worker
            .stdin
            .as_mut()
            .map(|stdin| stdin.write_all(line.as_bytes()).and_then(|()| stdin.flush()));
        if !matches!(sent, Some(Ok(()))) {
            return Err(ended(worker, "before it read the request"));
        }
        let answer = match worker.lines.recv_timeout(self.timeout) {
            Ok(Said::Line(answer)) => answer,
            Ok(Said::TooLong) => {
                return Err(fail(
                    FailureKind::Protocol,
                    format!("its response line is over {MAX_RESPONSE_LINE} bytes{}", said(worker)),
                ))
            }
            Ok(Said::End) | Err(RecvTimeoutError::Disconnected) => return Err(ended(worker, "without answering")),
            Err(RecvTimeoutError::Timeout) => {
                return Err(fail(
                    FailureKind::Timeout,
                    format!(
                        "no answer after {} s; killed{}",
                        self.timeout.as_secs_f64(),
                        said(worker)
                    ),
                ))
            }
        };
        let response: Value = serde_json::from_str(&answer).map_err(|e| {
            fail(
                FailureKind::Protocol,
                format!("its response is not JSON ({e}): {}{}", clip(&answer), said(worker)),
            )
        })?;
        if response.get("id").and_then(Value::as_u64) != Some(n) {
            return Err(fail(
                FailureKind::Protocol,
                format!(
                    "its response does not answer request {n} (a late or repeated answer?): {}{}",
                    clip(&answer),
                    said(worker)
                ),
            ));
        }
        match response.get("ok").and_then(Value::as_bool) {
            Some(true) => read_output(out, self.format, self.background, scene, &said(worker)),
            Some(false) => {
                let error = response
                    .get("error")
                    .and_then(Value::as_str)
                    .unwrap_or("(no error message)");
                Err(fail(
                    FailureKind::Exit,
                    format!("it answered an error: {}{}", clip(error), said(worker)),
                ))
            }
            None => Err(fail(
                FailureKind::Protocol,
                format!("its response has no boolean \"ok\": {}{}", clip(&answer), said(worker)),
            )),
        }
    }
}

impl Renderer for StayAlive {
    fn render(&self, scene: &Scene) -> Result<Theirs, RenderFailure> {
        StayAlive::render(self, scene)
    }

    fn runs(&self) -> Option<RendererRuns> {
        Some(RendererRuns {
            calls: self.requests(),
            starts: self.starts(),
        })
    }

    fn files_and_groups(&self) -> Option<(&Path, ProcessGroups)> {
        Some((self.temp_dir(), self.process_groups()))
    }
}

/// The failure of a program that closed its stdout `when`: its exit status (waited for a
/// moment), a crash when a signal ended it.
fn ended(worker: &mut Worker, when: &str) -> RenderFailure {
    let mut status = None;
    for _ in 0..100 {
        if let Ok(Some(s)) = worker.child.try_wait() {
            status = Some(s);
            break;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let said = stderr_tail(&worker.stderr);
    #[cfg(unix)]
    if let Some(signal) = status.and_then(|s| std::os::unix::process::ExitStatusExt::signal(&s)) {
        return RenderFailure {
            kind: FailureKind::Crash,
            message: format!("killed by signal {signal} {when}{said}"),
        };
    }
    RenderFailure {
        kind: FailureKind::Exit,
        message: match status {
            Some(s) => format!("it exited {when} ({s}){said}"),
            None => format!("it closed its stdout {when}{said}"),
        },
    }
}

/// The reader thread: each line of `stdout` (at most [`MAX_RESPONSE_LINE`] bytes) to
/// `send`, then [`Said::End`].
fn read_lines(stdout: impl std::io::Read, send: &mpsc::Sender<Said>) {
    let mut reader = BufReader::new(stdout);
    loop {
        let mut buf = Vec::new();
        let limit = u64::try_from(MAX_RESPONSE_LINE).expect("fits");
        match reader.by_ref().take(limit).read_until(b'\n', &mut buf) {
            Ok(0) | Err(_) => {
                let _ = send.send(Said::End);
                return;
            }
            Ok(_) if buf.last() != Some(&b'\n') => {
                // Cut short by the limit, or the last line without a newline at the end.
                let said = if buf.len() >= MAX_RESPONSE_LINE {
                    Said::TooLong
                } else {
                    Said::Line(String::from_utf8_lossy(&buf).into_owned())
                };
                let too_long = matches!(said, Said::TooLong);
                if send.send(said).is_err() || too_long {
                    return;
                }
            }
            Ok(_) => {
                buf.pop();
                if send
                    .send(Said::Line(String::from_utf8_lossy(&buf).into_owned()))
                    .is_err()
                {
                    return;
                }
            }
        }
    }
}

/// At most 200 characters of `text`, for a message.
fn clip(text: &str) -> String {
    let text = text.trim();
    match text.char_indices().nth(200) {
        Some((k, _)) => format!("{}...", &text[..k]),
        None => text.to_string(),
    }
}
