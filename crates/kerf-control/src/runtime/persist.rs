//! `--state DIR`: the tool offsets and retained variables in the files of
//! kerf_interp::state (`<profile>.offsets`, `<profile>.vars`) and the work
//! offsets in `<profile>.work`, each replaced atomically (temporary file,
//! fsync, rename, directory fsync): a kill at any instant leaves the old
//! or the new file, never a torn one, and a write is acknowledged only
//! after its file is on disk.
//!
//! ```text
//! # kerf work offsets: G54+index, machine coordinates x y z a b c
//! 0 -400 -250 -250 0 0 0
//! ```

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

use kerf_canon::NAXES;
use kerf_interp::state::StateError;
use kerf_interp::Interp;

use super::Runtime;
use crate::job::LoadError;

/// A `--state` folder that could not be read or written; the message
/// names the folder, or the file and line at fault.
#[derive(Debug, thiserror::Error)]
pub enum PersistError {
    /// The folder could not be created.
    #[error("{}: {source}", dir.display())]
    Folder {
        /// The folder.
        dir: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// The retained variables or tool offsets file.
    #[error(transparent)]
    State(#[from] StateError),
    /// The work offsets file could not be read.
    #[error("{}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// A line of the work offsets file that is not `INDEX X Y Z A B C`.
    #[error("{}:{line}: expected 'INDEX X Y Z A B C'", path.display())]
    WorkLine {
        /// The file.
        path: PathBuf,
        /// 1-based line number.
        line: usize,
    },
    /// A file could not be written.
    #[error("--state {}: {source}", dir.display())]
    Save {
        /// The folder.
        dir: PathBuf,
        /// What the system said.
        source: io::Error,
    },
}

impl From<PersistError> for String {
    fn from(e: PersistError) -> String {
        e.to_string()
    }
}

impl From<StateError> for LoadError {
    fn from(e: StateError) -> LoadError {
        LoadError(e.to_string())
    }
}

fn work_file(dir: &Path, it: &Interp) -> PathBuf {
    let f = kerf_interp::state::offsets_file(dir, &it.profile().name);
    f.with_extension("work")
}

/// Loads what `dir` keeps into the interpreter (missing files: nothing).
pub(super) fn load(dir: &Path, it: &mut Interp) -> Result<(), PersistError> {
    fs::create_dir_all(dir).map_err(|source| PersistError::Folder {
        dir: dir.to_path_buf(),
        source,
    })?;
    kerf_interp::state::load_retained(dir, it)?;
    kerf_interp::state::load_offsets(dir, it)?;
    let path = work_file(dir, it);
    let text = match fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(source) => return Err(PersistError::Read { path, source }),
    };
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let bad = || PersistError::WorkLine {
            path: path.clone(),
            line: n + 1,
        };
        let nums: Vec<f64> = line
            .split_whitespace()
            .map(|w| w.parse::<f64>().map_err(|_| bad()))
            .collect::<Result<_, _>>()?;
        if nums.len() != 1 + NAXES || nums[0].fract() != 0.0 || !(0.0..6.0).contains(&nums[0]) {
            return Err(bad());
        }
        let mut p = [0.0; NAXES];
        p.copy_from_slice(&nums[1..]);
        it.set_work_offset(nums[0] as usize, p);
    }
    Ok(())
}

/// Which files a save writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Part {
    /// Tool offsets.
    Tools,
    /// Work offsets.
    Work,
    /// Retained variables.
    Vars,
    /// All three.
    All,
}

/// Saves what `dir` keeps (the files of `part`).
pub(super) fn save(dir: &Path, it: &Interp, part: Part) -> Result<(), PersistError> {
    let err = |source: io::Error| PersistError::Save {
        dir: dir.to_path_buf(),
        source,
    };
    if matches!(part, Part::Tools | Part::All) {
        kerf_interp::state::save_offsets(dir, it).map_err(err)?;
    }
    if matches!(part, Part::Vars | Part::All) {
        kerf_interp::state::save_retained(dir, it).map_err(err)?;
    }
    if !matches!(part, Part::Work | Part::All) {
        return Ok(());
    }
    let mut text =
        String::from("# kerf work offsets: G54+index, machine coordinates x y z a b c\n");
    for i in 0..6 {
        let p = it.work_offset(i).unwrap_or([0.0; NAXES]);
        text.push_str(&i.to_string());
        for v in p {
            text.push(' ');
            text.push_str(&format!("{v:?}"));
        }
        text.push('\n');
    }
    kerf_interp::state::write_atomic(dir, &work_file(dir, it), &text).map_err(err)
}

impl Runtime {
    /// Saves `part` to `--state` now; the error names the folder.
    pub(super) fn save_state_now(&self, part: Part) -> Result<(), PersistError> {
        match &self.state_dir {
            Some(d) => save(d, &self.interp, part),
            None => Ok(()),
        }
    }

    /// Saves at the end of a run or a reset (the program may have written
    /// offsets and retained variables); a failure goes to the history.
    pub(super) fn save_state(&mut self) {
        if let Err(e) = self.save_state_now(Part::All) {
            let r = self.record(super::RecordKind::Message, "STATE", &e.to_string(), None);
            self.log.push(r);
        }
    }
}
