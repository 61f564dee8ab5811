//! Writing output files so that a failed run never leaves a truncated or partial file.
//!
//! - [`write_atomic`]: one file, through a temporary file in the same folder, `fsync` and
//!   `rename` (atomic on POSIX file systems).
//! - [`OutputDir`]: several files staged in a hidden folder inside the output folder and
//!   moved into place only by [`OutputDir::commit`]; dropped without a commit, it removes
//!   what it staged.

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes temporary names made by this process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A name no other writer in this process or another process uses at the same time:
/// `.{stem}.{pid}.{n}.tmp`, hidden.
fn unique_name(stem: &std::ffi::OsStr, suffix: &str) -> OsString {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let mut name = OsString::from(".");
    name.push(stem);
    name.push(format!(".{}.{n}.{suffix}", std::process::id()));
    name
}

/// Flushes a folder's entry table, so that a rename inside it survives a crash.
///
/// Best effort: some platforms (Windows) cannot open a folder as a file; there the rename
/// is as durable as the file system makes it.
fn sync_dir(dir: &Path) {
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
}

/// The folder holding `path` (`.` for a bare file name).
fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Creates `path` with `bytes` and flushes it to disk, failing if it exists.
fn write_new_synced(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = OpenOptions::new().write(true).create_new(true).open(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}

/// Writes `bytes` to `path` atomically: readers see the old file or the whole new one.
///
/// The bytes go to a hidden temporary file in the same folder (`.{name}.{pid}.{n}.tmp`),
/// which is flushed (`fsync`) and renamed over `path`; the folder is then flushed too. On
/// any error the temporary file is removed and `path` is untouched. The folder must exist.
///
/// # Errors
///
/// Any I/O error creating, writing, flushing or renaming; `InvalidInput` if `path` has no
/// file name.
///
/// # Example
///
/// ```
/// use armdyn::report::write_atomic;
///
/// let dir = std::env::temp_dir().join(format!("armdyn-doc-atomic-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("metrics.json");
/// write_atomic(&path, b"{}\n").unwrap();
/// assert_eq!(std::fs::read(&path).unwrap(), b"{}\n");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_atomic(path: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<()> {
    let path = path.as_ref();
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("`{}` has no file name", path.display()),
        )
    })?;
    let dir = parent_of(path);
    let tmp = dir.join(unique_name(name, "tmp"));
    let result = write_new_synced(&tmp, bytes.as_ref()).and_then(|()| fs::rename(&tmp, path));
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
        return result;
    }
    sync_dir(dir);
    Ok(())
}

/// A set of output files written all together or not at all.
///
/// Files written with [`OutputDir::write`] go to a hidden staging folder inside the output
/// folder (same file system, so the final move is a rename). [`OutputDir::commit`] moves
/// them all into place; dropping an `OutputDir` without committing removes the staging
/// folder and everything in it, so a run that fails half-way leaves the output folder as
/// it was.
///
/// Each file is replaced atomically. The set as a whole is not: if a rename fails during
/// [`OutputDir::commit`] (a full disk does not cause this, since the data is already
/// written; a permission change could), the files moved before it stay, each complete.
///
/// # Example
///
/// ```
/// use armdyn::report::OutputDir;
///
/// let dir = std::env::temp_dir().join(format!("armdyn-doc-outdir-{}", std::process::id()));
/// let mut out = OutputDir::create(&dir).unwrap();
/// out.write("trajectory.csv", "t_s\n0\n").unwrap();
/// out.write("plots/force.svg", "<svg/>").unwrap();
/// assert!(!dir.join("trajectory.csv").exists()); // staged, not yet visible
/// let written = out.commit().unwrap();
/// assert_eq!(written.len(), 2);
/// assert!(dir.join("plots/force.svg").exists());
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
#[derive(Debug)]
pub struct OutputDir {
    dir: PathBuf,
    staging: PathBuf,
    /// Relative names in write order, each once.
    staged: Vec<PathBuf>,
    committed: bool,
}

impl OutputDir {
    /// Creates the output folder `dir` (and its parents) if needed, and a fresh hidden
    /// staging folder inside it.
    ///
    /// # Errors
    ///
    /// Any I/O error creating either folder.
    pub fn create(dir: impl AsRef<Path>) -> io::Result<Self> {
        let dir = dir.as_ref().to_path_buf();
        fs::create_dir_all(&dir)?;
        let staging = dir.join(unique_name("armdyn-staging".as_ref(), "partial"));
        fs::create_dir(&staging)?;
        Ok(Self {
            dir,
            staging,
            staged: Vec::new(),
            committed: false,
        })
    }

    /// The output folder.
    pub fn path(&self) -> &Path {
        &self.dir
    }

    /// Where `name` will be once committed.
    pub fn final_path(&self, name: impl AsRef<Path>) -> PathBuf {
        self.dir.join(name)
    }

    /// The relative names staged so far, in the order first written.
    pub fn staged(&self) -> &[PathBuf] {
        &self.staged
    }

    /// Stages a file. `name` is relative to the output folder and may contain subfolders
    /// (`plots/force.svg`), but no `..`, root or prefix. Writing the same name again
    /// replaces the staged content.
    ///
    /// # Errors
    ///
    /// `InvalidInput` for an unusable name; any I/O error writing or flushing.
    pub fn write(&mut self, name: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<()> {
        let name = name.as_ref();
        check_relative(name)?;
        let staged = self.staging.join(name);
        if let Some(parent) = staged.parent() {
            fs::create_dir_all(parent)?;
        }
        write_atomic(&staged, bytes)?;
        if !self.staged.iter().any(|n| n == name) {
            self.staged.push(name.to_path_buf());
        }
        Ok(())
    }

    /// Moves every staged file into the output folder (replacing files of the same name),
    /// flushes the folders and removes the staging folder. Returns the final paths, in the
    /// order first written.
    ///
    /// # Errors
    ///
    /// Any I/O error creating a subfolder or renaming; the files not yet moved are then
    /// removed with the staging folder.
    pub fn commit(mut self) -> io::Result<Vec<PathBuf>> {
        let mut written = Vec::with_capacity(self.staged.len());
        let mut dirs: Vec<PathBuf> = Vec::new();
        for name in &self.staged {
            let to = self.dir.join(name);
            let parent = parent_of(&to).to_path_buf();
            fs::create_dir_all(&parent)?;
            fs::rename(self.staging.join(name), &to)?;
            if !dirs.contains(&parent) {
                dirs.push(parent);
            }
            written.push(to);
        }
        for d in &dirs {
            sync_dir(d);
        }
        self.committed = true;
        fs::remove_dir_all(&self.staging)?;
        sync_dir(&self.dir);
        Ok(written)
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        // After a successful commit the staging folder is already gone; after a failed one
        // (or none) it holds what was not moved.
        if self.staging.exists() {
            let _ = fs::remove_dir_all(&self.staging);
        }
    }
}

/// Accepts only plain relative names: normal components, at least one.
fn check_relative(name: &Path) -> io::Result<()> {
    let ok = name.components().count() > 0
        && name.components().all(|c| matches!(c, Component::Normal(_)));
    if ok {
        Ok(())
    } else {
        Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "output file name `{}` must be relative, without `..`",
                name.display()
            ),
        ))
    }
}
