//! The command line (clap): subcommands and options.

use std::path::PathBuf;

use clap::{Parser, Subcommand};
use kerf_control::Job;

/// The `kerf` command.
#[derive(Parser)]
#[command(
    name = "kerf",
    version,
    about = "A software CNC control: runs Fanuc-family part programs as the real control would"
)]
pub struct Cli {
    #[command(subcommand)]
    pub cmd: Cmd,
}

/// Options every command that runs a program takes.
#[derive(clap::Args, Clone)]
pub struct Common {
    /// The part program.
    pub program: PathBuf,
    /// Machine profile: a built-in name (see `kerf machines`) or a TOML file.
    #[arg(long, default_value = kerf_control::job::DEFAULT_MACHINE)]
    pub machine: String,
    /// Folder of library programs (subprograms, macros); may repeat.
    #[arg(long = "lib")]
    pub lib: Vec<PathBuf>,
    /// Operator switches and parameters: block_skip=1,2 optional_stop=on
    /// single_block=on dry_run=on, "PI 144=1" … (see docs/formats.md).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Work offsets file (TOML, see docs/formats.md).
    #[arg(long)]
    pub offsets: Option<PathBuf>,
    /// Folder keeping the retained macro variables across runs (#200-#699
    /// on the HX, #500-#999 on the Fanuc lathes; docs/formats.md).
    #[arg(long, value_name = "DIR")]
    pub state: Option<PathBuf>,
    /// Print nothing on success (warnings and alarms still go to stderr).
    #[arg(long, short)]
    pub quiet: bool,
    /// Print the report (JSON) on stdout instead of the summary.
    #[arg(long, conflicts_with = "quiet")]
    pub json: bool,
}

impl Common {
    /// The job these options describe; `check` reads the state but does
    /// not write it.
    pub fn job(&self, check: bool) -> Job {
        let mut job = Job::file(&self.program).machine(&self.machine);
        for dir in &self.lib {
            job = job.lib(dir);
        }
        for kv in &self.set {
            job = job.set(kv);
        }
        if let Some(p) = &self.offsets {
            job = job.offsets(p);
        }
        if let Some(d) = &self.state {
            job = job.state(d);
        }
        if check {
            job = job.read_only();
        }
        job
    }
}

/// The output files of `kerf run`.
#[derive(clap::Args, Clone, Default)]
pub struct Outputs {
    /// Write every motion as JSON Lines.
    #[arg(long)]
    pub toolpath: Option<PathBuf>,
    /// Write a JSON summary of the run.
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// Write a plot of the toolpath: PNG when FILE ends in .png, SVG
    /// otherwise (axes in mm, a colour per tool, rapids dashed; see
    /// docs/formats.md).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Write the smoothed axis setpoints every DT seconds (e.g. 0.001)
    /// to FILE as CSV (docs/formats.md).
    #[arg(long, num_args = 2, value_names = ["DT", "FILE"])]
    pub sample: Vec<String>,
    /// Write the operator messages (Hurco probe records, #3006 …), one
    /// per line.
    #[arg(long)]
    pub log: Option<PathBuf>,
    /// Simulate the cut from this stock: box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX
    /// (machining center), bar:DIAMETER,LENGTH[,FACE_Z] or
    /// tube:OD,ID,LENGTH[,FACE_Z] (lathes), work coordinates, mm.
    #[arg(long, value_name = "SPEC")]
    pub stock: Option<String>,
    /// Tool geometry for the simulation (TOML, docs/sim.md).
    #[arg(long, value_name = "FILE.toml")]
    pub tools: Option<PathBuf>,
    /// Write the simulated part as binary STL.
    #[arg(long, value_name = "FILE.stl")]
    pub stl: Option<PathBuf>,
    /// Write a picture of the simulated part (PNG).
    #[arg(long, value_name = "FILE.png")]
    pub png: Option<PathBuf>,
    /// Simulation cell size, mm (default: the finest that fits 64 MB on
    /// the machining center, 0.005 on the lathes).
    #[arg(long, value_name = "MM")]
    pub sim_res: Option<String>,
}

/// The subcommands (parsed once; the size of `Run` does not matter).
#[derive(Subcommand)]
#[allow(clippy::large_enum_variant)]
pub enum Cmd {
    /// Run a program and write what it does.
    Run {
        #[command(flatten)]
        common: Common,
        #[command(flatten)]
        outputs: Outputs,
    },
    /// Check a program: run it without writing any file (not even the
    /// --state folder); print the same summary, warnings and alarms.
    Check {
        #[command(flatten)]
        common: Common,
    },
    /// Write the program as plain G-code for another control: every macro,
    /// call, cycle, compensation, transform and offset resolved
    /// (docs/expand.md).
    Expand {
        #[command(flatten)]
        common: Common,
        /// Target: `fanuc` (the same kind of control) or `linuxcnc`.
        #[arg(long, default_value = "fanuc", value_parser = ["fanuc", "linuxcnc"])]
        to: String,
        /// Output file (default: standard output).
        #[arg(short = 'o', long = "output", value_name = "OUT.nc")]
        out: Option<PathBuf>,
    },
    /// List the built-in machine profiles.
    Machines,
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell).
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// Print the manual page (roff; `kerf man | man -l -`).
    Man,
    /// Serve the operator screen and its API (docs/hmi.md).
    Serve(crate::serve::Args),
}
