//! The output files of `kerf run` checked before the run starts: each
//! path can be written (its folder exists, it is not a folder, the file
//! can be opened for writing), so that a mistyped `--plot` fails at once
//! instead of after an hour's run, and no output is created or emptied
//! when another one cannot be written.

use std::fs::OpenOptions;
use std::io;
use std::path::Path;

/// Why an output path cannot be written: the option, the path, the cause.
#[derive(Debug, thiserror::Error)]
#[error("{option} {}: {reason}", path.display())]
pub struct OutputPathError {
    /// `--plot` …
    pub option: &'static str,
    /// The path as given.
    pub path: std::path::PathBuf,
    /// What is wrong, as a user reads it.
    pub reason: String,
}

/// Checks that `path` (given with `option`) can be written without
/// changing anything: an existing file is opened for writing without
/// truncating it, a new one is created and removed again.
pub fn check_writable(option: &'static str, path: &Path) -> Result<(), OutputPathError> {
    let fail = |reason: String| OutputPathError {
        option,
        path: path.to_path_buf(),
        reason,
    };
    if path.is_dir() {
        return Err(fail("is a folder, not a file".into()));
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !parent.is_dir() {
        return Err(fail(format!("no folder {}", parent.display())));
    }
    let existed = path.exists();
    OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
        .map_err(|e| fail(io_reason(&e)))?;
    if !existed {
        let _ = std::fs::remove_file(path);
    }
    Ok(())
}

/// The system's message for `e` without the trailing `(os error N)`.
pub fn io_reason(e: &io::Error) -> String {
    strip_os_error(&e.to_string()).to_string()
}

/// `s` without a trailing ` (os error N)`.
pub fn strip_os_error(s: &str) -> &str {
    match s.rfind(" (os error ") {
        Some(i)
            if s.ends_with(')') && s[i + 11..s.len() - 1].bytes().all(|b| b.is_ascii_digit()) =>
        {
            &s[..i]
        }
        _ => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> std::path::PathBuf {
        let d = std::env::temp_dir().join(format!("kerf_output_paths_{name}"));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_new_file_in_a_folder_is_writable_and_is_not_left_behind() {
        let d = dir("new");
        let p = d.join("out.svg");
        check_writable("--plot", &p).unwrap();
        assert!(!p.exists());
    }

    #[test]
    fn an_existing_file_is_not_emptied() {
        let d = dir("existing");
        let p = d.join("out.json");
        std::fs::write(&p, "kept").unwrap();
        check_writable("--report", &p).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "kept");
    }

    #[test]
    fn a_missing_folder_or_a_folder_is_named() {
        let d = dir("missing");
        let e = check_writable("--plot", &d.join("no/out.svg")).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "--plot {}: no folder {}",
                d.join("no/out.svg").display(),
                d.join("no").display()
            )
        );
        let e = check_writable("--toolpath", &d).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("--toolpath {}: is a folder, not a file", d.display())
        );
    }

    #[test]
    fn the_os_error_number_is_left_out() {
        let e = io::Error::from_raw_os_error(13);
        assert_eq!(io_reason(&e), "Permission denied");
        let e = io::Error::other("plain");
        assert_eq!(io_reason(&e), "plain");
        assert_eq!(
            strip_os_error("a.nc: No such file or directory (os error 2)"),
            "a.nc: No such file or directory"
        );
        assert_eq!(
            strip_os_error("see (os error notes)"),
            "see (os error notes)"
        );
    }
}
