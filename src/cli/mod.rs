//! Subcommands of the binary.

pub mod check;
pub mod clip;
pub mod flood;
pub mod render;

/// The `--model` help: every model with its one-line description, from
/// [`rasterproof::model::Model::ALL`] (a new model appears here by itself).
pub fn model_help() -> String {
    let mut s = String::from("The model that renders the scene (default exact-snapped):");
    for m in rasterproof::model::Model::ALL {
        s.push_str(&format!("\n  {:<14} {}", m.name(), m.describe()));
    }
    s
}

/// Writes to stdout through a buffer; a closed pipe (`| head`) ends quietly instead of
/// panicking.
pub fn write_stdout(body: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>) -> Result<(), String> {
    use std::io::Write as _;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    match body(&mut out).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(format!("cannot write to stdout: {e}")),
    }
}

/// Writes one line to stdout (see [`write_stdout`]).
pub fn print_stdout(line: &str) -> Result<(), String> {
    write_stdout(|out| writeln!(out, "{line}"))
}
