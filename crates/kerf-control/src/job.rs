//! [`Job`]: what to load for a run (the program, the machine profile by
//! name or file, library folders, `--set` settings and overrides, an
//! offsets file, the retained-state folder) and [`Job::load`], which
//! builds the interpreter and the planner's dynamics from it and returns
//! a [`Runner`] ready to step.

use std::fmt;
use std::path::{Path, PathBuf};

use kerf_interp::machine::BUILTIN;
use kerf_interp::{Interp, Profile};

use crate::runner::Runner;

/// A program or profile that could not be loaded; the message names the
/// file or the option (`--lib`, `--set`, `--state` …) at fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadError(pub String);

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for LoadError {}

impl From<String> for LoadError {
    fn from(s: String) -> LoadError {
        LoadError(s)
    }
}

/// Where the main program comes from.
#[derive(Clone, Debug)]
pub enum Source {
    /// A file on disk (read as it runs).
    File(PathBuf),
    /// Program text in memory, with the name alarms give it.
    Text {
        /// The file name shown in alarms and records.
        name: String,
        /// The program.
        text: String,
    },
}

/// Everything needed to load a run. Built with the chained setters, then
/// [`Job::load`].
#[derive(Clone, Debug)]
pub struct Job {
    source: Source,
    machine: String,
    libs: Vec<PathBuf>,
    sets: Vec<String>,
    offsets: Option<PathBuf>,
    state: Option<PathBuf>,
    read_only: bool,
}

/// The default machine profile.
pub const DEFAULT_MACHINE: &str = "hx-mc";

impl Job {
    /// A job for a program file, on the default machine.
    pub fn file(path: impl Into<PathBuf>) -> Job {
        Job::from_source(Source::File(path.into()))
    }

    /// A job for program text in memory, on the default machine.
    pub fn text(name: impl Into<String>, text: impl Into<String>) -> Job {
        Job::from_source(Source::Text {
            name: name.into(),
            text: text.into(),
        })
    }

    fn from_source(source: Source) -> Job {
        Job {
            source,
            machine: DEFAULT_MACHINE.to_string(),
            libs: Vec::new(),
            sets: Vec::new(),
            offsets: None,
            state: None,
            read_only: false,
        }
    }

    /// The machine profile: a built-in name or a TOML file.
    pub fn machine(mut self, name_or_file: impl Into<String>) -> Job {
        self.machine = name_or_file.into();
        self
    }

    /// Adds a folder of library programs (subprograms, macros).
    pub fn lib(mut self, dir: impl Into<PathBuf>) -> Job {
        self.libs.push(dir.into());
        self
    }

    /// Adds one `KEY=VALUE` setting (operator switches, parameters,
    /// `feed_override` / `rapid_override`; docs/formats.md).
    pub fn set(mut self, key_value: impl Into<String>) -> Job {
        self.sets.push(key_value.into());
        self
    }

    /// A work offsets file (TOML), applied on top of the retained state.
    pub fn offsets(mut self, path: impl Into<PathBuf>) -> Job {
        self.offsets = Some(path.into());
        self
    }

    /// The folder keeping the retained variables and offsets across runs:
    /// read at load, written at the end of the run.
    pub fn state(mut self, dir: impl Into<PathBuf>) -> Job {
        self.state = Some(dir.into());
        self
    }

    /// Reads the retained state but never writes it (nor creates the
    /// folder): what `kerf check` does.
    pub fn read_only(mut self) -> Job {
        self.read_only = true;
        self
    }

    /// The program's name as alarms and records show it.
    pub fn program_name(&self) -> String {
        match &self.source {
            Source::File(p) => p.display().to_string(),
            Source::Text { name, .. } => name.clone(),
        }
    }

    /// Loads the profile, settings, program, libraries, retained state and
    /// offsets, in that order, and returns the runner.
    pub fn load(&self) -> Result<Runner, LoadError> {
        let mut profile = load_profile(&self.machine)?;
        let (feed_ovr, rapid_ovr, sets) = split_overrides(&self.sets)?;
        let settings =
            crate::settings::parse(&sets, &mut profile).map_err(|e| suggest_key(e, &profile))?;
        let dynamics =
            crate::dynamics::dynamics_of(&profile, feed_ovr, rapid_ovr, settings.dry_run)
                .map_err(|e| format!("machine {}: {e}", self.machine))?;
        let opened = match &self.source {
            Source::File(p) => crate::source::open_file(p)?,
            Source::Text { name, text } => crate::source::open_text(name, text.as_bytes())?,
        };
        let mut it = Interp::new(profile, settings);
        for dir in &self.libs {
            if !dir.is_dir() {
                return Err(format!("--lib {}: not a folder", dir.display()).into());
            }
            it.add_lib_dir(dir.clone());
        }
        if let Some(dir) = &self.state {
            if !self.read_only || dir.exists() {
                load_state(dir, &mut it, !self.read_only)?;
            }
        }
        if let Some(path) = &self.offsets {
            crate::offsets::load(path, &mut it)?;
        }
        let lint = self.lint(it.profile());
        it.load_main(&self.program_name(), opened.reader);
        let mut runner = Runner::new(it, dynamics);
        runner.lint_with(lint);
        runner.track_source(opened.len, opened.read);
        if let Some(dir) = self.state.as_ref().filter(|_| !self.read_only) {
            runner.save_state_to(dir.clone());
        }
        Ok(runner)
    }
}

impl Job {
    /// Starts the decimal-point check of the main program: on its own
    /// thread for a file (it reads the file a second time), at once for
    /// text in memory.
    fn lint(&self, profile: &Profile) -> Lint {
        let name = self.program_name();
        match &self.source {
            Source::File(path) => {
                let (profile, path) = (profile.clone(), path.clone());
                Lint::Running(std::thread::spawn(move || {
                    let opened = crate::source::open_file(&path).ok()?;
                    crate::lint::decimal_points(&profile, &name, opened.reader).ok()
                }))
            }
            Source::Text { text, .. } => {
                let found = crate::source::open_text(&name, text.as_bytes())
                    .ok()
                    .and_then(|o| crate::lint::decimal_points(profile, &name, o.reader).ok());
                Lint::Done(found.unwrap_or_default())
            }
        }
    }
}

/// The decimal-point check of a run: running beside it, or done.
pub enum Lint {
    /// On its own thread (`None` if the file could not be read again).
    Running(std::thread::JoinHandle<Option<Vec<crate::Warning>>>),
    /// Its warnings.
    Done(Vec<crate::Warning>),
}

impl Lint {
    /// Its warnings, waiting for the thread if it still runs.
    pub fn join(self) -> Vec<crate::Warning> {
        match self {
            Lint::Running(h) => h.join().ok().flatten().unwrap_or_default(),
            Lint::Done(w) => w,
        }
    }
}

/// A machine profile by built-in name or TOML file.
pub fn load_profile(name: &str) -> Result<Profile, LoadError> {
    if let Some(p) = Profile::builtin(name) {
        return Ok(p);
    }
    if name.ends_with(".toml") || Path::new(name).exists() {
        let text = std::fs::read_to_string(name).map_err(|e| format!("{name}: {e}"))?;
        return Ok(Profile::from_toml(&text).map_err(|e| format!("{name}: {e}"))?);
    }
    let names: Vec<&str> = BUILTIN.iter().map(|(n, _)| *n).collect();
    let hint = match crate::suggest::closest(name, names.iter().copied()) {
        Some(n) => format!(": did you mean '{n}'?"),
        None => String::new(),
    };
    Err(format!(
        "unknown machine '{name}'{hint} (built-in: {})",
        names.join(", ")
    )
    .into())
}

/// Adds "did you mean" to an unknown `--set` key error.
fn suggest_key(err: crate::settings::SettingsError, profile: &Profile) -> String {
    let crate::settings::SettingsError::UnknownKey { key } = &err else {
        return err.to_string();
    };
    let params = profile.params.keys().map(String::as_str);
    match crate::suggest::closest(
        key,
        crate::settings::KEYS
            .iter()
            .copied()
            .chain(["feed_override", "rapid_override"])
            .chain(params),
    ) {
        Some(k) => format!("--set {key}: unknown key; did you mean '{k}'? (see docs/formats.md)"),
        None => err.to_string(),
    }
}

/// Takes the planner's overrides (`feed_override`, `rapid_override`,
/// percentages 1-1000) out of the settings; returns them and the rest.
fn split_overrides(sets: &[String]) -> Result<(f64, f64, Vec<String>), LoadError> {
    let (mut feed, mut rapid) = (100.0, 100.0);
    let mut rest = Vec::new();
    for kv in sets {
        match kv.split_once('=').map(|(k, v)| (k.trim(), v.trim())) {
            Some((k @ ("feed_override" | "rapid_override"), v)) => {
                let Some(pct) = v.parse::<f64>().ok().filter(|p| (1.0..=1000.0).contains(p)) else {
                    return Err(format!("--set {k}={v}: expected a percentage 1-1000").into());
                };
                if k == "feed_override" {
                    feed = pct;
                } else {
                    rapid = pct;
                }
            }
            _ => rest.push(kv.clone()),
        }
    }
    Ok((feed, rapid, rest))
}

/// Reads the retained variables and offsets kept in `dir` (created when
/// missing and `create`).
fn load_state(dir: &Path, it: &mut Interp, create: bool) -> Result<(), LoadError> {
    if create {
        std::fs::create_dir_all(dir).map_err(|e| format!("--state {}: {e}", dir.display()))?;
    }
    kerf_interp::state::load_retained(dir, it)?;
    kerf_interp::state::load_offsets(dir, it)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_are_taken_out_of_the_settings() {
        let sets = vec![
            "feed_override=150".to_string(),
            "dry_run=on".to_string(),
            " rapid_override = 25 ".to_string(),
        ];
        let (f, r, rest) = split_overrides(&sets).unwrap();
        assert_eq!((f, r), (150.0, 25.0));
        assert_eq!(rest, vec!["dry_run=on".to_string()]);
        let bad = split_overrides(&["feed_override=0".to_string()]).unwrap_err();
        assert!(bad.0.contains("1-1000"), "{bad}");
    }

    #[test]
    fn an_unknown_machine_lists_the_built_in_ones() {
        let e = load_profile("no-such-machine").unwrap_err();
        assert!(e.0.contains("hx-mc") && e.0.contains("puma-lathe"), "{e}");
        assert!(!e.0.contains("did you mean"), "{e}");
        let e = load_profile("puma-lahte").unwrap_err();
        assert!(e.0.contains("did you mean 'puma-lathe'?"), "{e}");
    }

    #[test]
    fn an_unknown_set_key_gets_the_closest_one() {
        let e = Job::text("t.nc", "M30\n")
            .set("dryrun=on")
            .load()
            .err()
            .unwrap();
        assert_eq!(
            e.0,
            "--set dryrun: unknown key; did you mean 'dry_run'? (see docs/formats.md)"
        );
        let e = Job::text("t.nc", "M30\n")
            .set("zzzzzz=1")
            .load()
            .err()
            .unwrap();
        assert_eq!(e.0, "--set zzzzzz: unknown key (see docs/formats.md)");
    }

    #[test]
    fn check_reads_the_state_but_leaves_no_folder() {
        let dir = std::env::temp_dir().join(format!("kerf-ro-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let r = Job::text("t.nc", "#500=1\nM30\n")
            .state(&dir)
            .read_only()
            .load();
        let out = r.unwrap().run(&mut []).unwrap();
        assert!(out.alarm.is_none());
        assert!(!dir.exists());
    }

    #[test]
    fn a_library_path_that_is_not_a_folder_is_refused() {
        let e = Job::text("t.nc", "G0 X1\nM30\n")
            .lib("/no/such/folder")
            .load()
            .err()
            .unwrap();
        assert_eq!(e.0, "--lib /no/such/folder: not a folder");
    }
}
