//! A folder of its own for one test's files: empty when made, removed when the test passes,
//! kept when it fails (its path printed with the failure), so that a failed run's outputs can
//! be read and a passing one leaves nothing behind in the system's temporary folder.

use std::ops::Deref;
use std::path::Path;

/// A test's folder (see the module); derefs to its [`Path`].
pub struct Scratch(Option<tempfile::TempDir>);

impl Scratch {
    /// A new empty folder `armdyn-{name}-XXXXXX` in the system's temporary folder (the suffix
    /// random, so that test processes running at once never share one).
    pub fn new(name: &str) -> Self {
        let dir = tempfile::Builder::new()
            .prefix(&format!("armdyn-{name}-"))
            .tempdir()
            .expect("making a folder in the system's temporary folder");
        Self(Some(dir))
    }
}

impl Deref for Scratch {
    type Target = Path;

    fn deref(&self) -> &Path {
        self.0.as_ref().expect("the folder lives until drop").path()
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        self
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let Some(dir) = self.0.take() else { return };
        if std::thread::panicking() {
            eprintln!(
                "the failed test's files are kept in {}",
                dir.keep().display()
            );
        }
        // Otherwise the `TempDir` removes the folder as it drops here.
    }
}

#[test]
fn a_scratch_folder_goes_when_its_test_passes_and_stays_when_it_fails() {
    let passed = Scratch::new("scratch-passed");
    std::fs::write(passed.join("a.txt"), "x").unwrap();
    let path = passed.to_path_buf();
    drop(passed);
    assert!(!path.exists(), "{} left behind", path.display());

    let kept = std::sync::Mutex::new(None);
    let failed = std::panic::catch_unwind(|| {
        let dir = Scratch::new("scratch-failed");
        std::fs::write(dir.join("a.txt"), "x").unwrap();
        *kept.lock().unwrap() = Some(dir.to_path_buf());
        panic!("a failing test");
    });
    assert!(failed.is_err());
    let path = kept.into_inner().unwrap().unwrap();
    assert!(path.join("a.txt").is_file(), "{} not kept", path.display());
    std::fs::remove_dir_all(&path).unwrap();
}
