//! Atomic output of a set of files into a directory.
//!
//! The subcommands compute everything in memory first, then hand the finished
//! files to [`write_atomically`]: they are written into a fresh temporary
//! directory next to the target (`<out>.tmp-<pid>`), and moved into place only
//! after every write succeeded. Each run owns its whole folder: if the target
//! does not exist, the temporary directory is renamed to it in one step; if it
//! holds an earlier maugis run (marked by the file [`MARKER`]) or is empty, it is
//! moved aside, the new folder renamed into place and the old one removed, so
//! no stale file of an earlier run remains. A non-empty directory without the
//! marker is refused before anything is computed. On any error the temporary
//! directory is removed and the target is left as it was.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `text` to stdout. A closed pipe (`maugis curve --format json | head`)
/// ends the output quietly; other write errors are reported.
pub fn print_stdout(text: &str) -> Result<(), String> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(format!("cannot write to stdout: {e}")),
    }
}

/// One finished output file.
pub struct OutFile {
    /// File name inside the output directory (no path separators).
    pub name: String,
    /// Contents.
    pub bytes: Vec<u8>,
}

impl OutFile {
    /// A file from text.
    pub fn text(name: impl Into<String>, text: String) -> OutFile {
        OutFile { name: name.into(), bytes: text.into_bytes() }
    }
}

/// The file that marks a folder as a maugis output folder (safe to replace).
pub const MARKER: &str = ".maugis-output";

/// Checks, before any computation, that `out` can be used as an output
/// directory: missing, empty, or the folder of an earlier maugis run.
pub fn check_out_dir(out: &Path) -> Result<(), String> {
    if out.as_os_str().is_empty() {
        return Err("--out must not be empty".into());
    }
    if out.exists() {
        if !out.is_dir() {
            return Err(format!("--out {}: exists and is not a directory", out.display()));
        }
        let empty = fs::read_dir(out).map_err(|e| format!("--out {}: cannot read it: {e}", out.display()))?.next().is_none();
        if !empty && !out.join(MARKER).is_file() {
            return Err(format!(
                "--out {}: a non-empty directory that maugis did not write (no {MARKER}); choose a new or empty directory",
                out.display()
            ));
        }
    }
    Ok(())
}

/// Removes the temporary directory when dropped (unless disarmed).
struct TempDirGuard {
    path: PathBuf,
    armed: bool,
}

impl Drop for TempDirGuard {
    fn drop(&mut self) {
        if self.armed {
            let _ = fs::remove_dir_all(&self.path);
        }
    }
}

/// Writes `files` into `out` atomically (see the module docs). Returns the final
/// paths of the files.
pub fn write_atomically(out: &Path, files: &[OutFile]) -> Result<Vec<PathBuf>, String> {
    check_out_dir(out)?;
    // A usable name for the sibling temporary directory.
    let out: PathBuf = if out.exists() {
        fs::canonicalize(out).map_err(|e| format!("cannot resolve {}: {e}", out.display()))?
    } else {
        out.to_path_buf()
    };
    let name = out
        .file_name()
        .ok_or_else(|| format!("--out {}: not a usable directory name", out.display()))?
        .to_string_lossy()
        .into_owned();
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&parent).map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    let tmp = parent.join(format!("{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        fs::remove_dir_all(&tmp).map_err(|e| format!("cannot remove stale {}: {e}", tmp.display()))?;
    }
    fs::create_dir(&tmp).map_err(|e| format!("cannot create {}: {e}", tmp.display()))?;
    let mut guard = TempDirGuard { path: tmp.clone(), armed: true };

    let marker = OutFile::text(MARKER, "This folder is written by maugis; each run replaces it whole.\n".to_string());
    for f in files.iter().chain(std::iter::once(&marker)) {
        if f.name.contains('/') || f.name.contains('\\') || f.name.is_empty() {
            return Err(format!("internal error: bad output file name {:?}", f.name));
        }
        let path = tmp.join(&f.name);
        let mut file = fs::File::create(&path).map_err(|e| format!("cannot create {}: {e}", path.display()))?;
        file.write_all(&f.bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        file.sync_all().map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }

    let finals: Vec<PathBuf> = files.iter().map(|f| out.join(&f.name)).collect();
    if !out.exists() {
        // One atomic step: the whole directory appears at once.
        fs::rename(&tmp, &out).map_err(|e| format!("cannot move {} to {}: {e}", tmp.display(), out.display()))?;
        guard.armed = false;
    } else {
        // Replace the earlier run's folder whole: move it aside, move the new one in.
        let old = parent.join(format!("{name}.old-{}", std::process::id()));
        if old.exists() {
            fs::remove_dir_all(&old).map_err(|e| format!("cannot remove stale {}: {e}", old.display()))?;
        }
        fs::rename(&out, &old).map_err(|e| format!("cannot move {} aside: {e}", out.display()))?;
        if let Err(e) = fs::rename(&tmp, &out) {
            let _ = fs::rename(&old, &out);
            return Err(format!("cannot move {} to {}: {e}", tmp.display(), out.display()));
        }
        guard.armed = false;
        fs::remove_dir_all(&old).map_err(|e| format!("cannot remove the earlier run {}: {e}", old.display()))?;
    }
    Ok(finals)
}

/// Checks, before any computation, that `path` (given with `flag`) can take a
/// file: not a directory, and its folder exists.
pub fn check_file_target(flag: &str, path: &Path) -> Result<(), String> {
    if path.is_dir() {
        return Err(format!("{flag} {}: is a directory; give a file", path.display()));
    }
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        if !parent.is_dir() {
            return Err(format!("{flag} {}: the folder {} does not exist", path.display(), parent.display()));
        }
    }
    Ok(())
}

/// Writes `text` to the file `path` atomically (a sibling temporary file, renamed).
pub fn write_file_atomically(flag: &str, path: &Path, text: &str) -> Result<(), String> {
    let tmp = path.with_extension(format!("tmp-{}", std::process::id()));
    fs::write(&tmp, text).and_then(|_| fs::rename(&tmp, path)).map_err(|e| {
        let _ = fs::remove_file(&tmp);
        format!("{flag} {}: {e}", path.display())
    })
}
