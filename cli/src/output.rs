//! Atomic output of a set of files into a directory.
//!
//! The subcommands compute everything in memory first, then hand the finished
//! files to [`write_atomically`]: they are written into a fresh temporary
//! directory next to the target (`<out>.tmp-<pid>`), and moved into place only
//! after every write succeeded. If the target directory does not exist yet, the
//! whole temporary directory is renamed to it in one step; otherwise each file is
//! renamed into the existing directory (same file system, so each rename is
//! atomic). On any error the temporary directory is removed and the target is
//! left as it was.

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

/// Checks, before any computation, that `out` can be used as an output
/// directory: it is either missing or an existing directory.
pub fn check_out_dir(out: &Path) -> Result<(), String> {
    if out.as_os_str().is_empty() {
        return Err("--out must not be empty".into());
    }
    if out.exists() && !out.is_dir() {
        return Err(format!("--out {}: exists and is not a directory", out.display()));
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

    for f in files {
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
        for f in files {
            let (from, to) = (tmp.join(&f.name), out.join(&f.name));
            fs::rename(&from, &to).map_err(|e| format!("cannot move {} to {}: {e}", from.display(), to.display()))?;
        }
        // `guard` removes the (now empty) temporary directory.
    }
    Ok(finals)
}
