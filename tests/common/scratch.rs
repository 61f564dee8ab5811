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
