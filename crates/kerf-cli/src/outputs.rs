//! Opens the output files of `kerf run` as kerf-control sinks.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use kerf_control::sinks::plot::PlotFormat;
use kerf_control::sinks::sim::check_stock;
use kerf_control::sinks::{Log, Plot, Report, Sample, SimSink, Toolpath, ToolpathBehind};
use kerf_control::Sink;
use kerf_interp::machine::MachineKind;
use kerf_interp::Profile;
use kerf_sim::Stock;

use crate::args::Outputs;
use crate::output_paths::{check_writable, io_reason};

type Out = BufWriter<File>;

fn create(path: &Path) -> Result<Out, String> {
    File::create(path)
        .map(|f| BufWriter::with_capacity(1 << 16, f))
        .map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))
}

/// The toolpath: formatted and written by a thread of its own (the
/// interpreter and the planner keep this one), in 1 MiB writes (the
/// sink gathers its lines itself: no `BufWriter`).
fn toolpath(path: &Path) -> Result<ToolpathBehind<File>, String> {
    File::create(path)
        .map(|f| ToolpathBehind::new(Toolpath::new(f)))
        .map_err(|e| format!("{}: {}", path.display(), io_reason(&e)))
}

/// `--sample DT FILE`: the period (0.00001-1 s) and the file.
fn sample_arg(sample: &[String]) -> Result<Option<(f64, PathBuf)>, String> {
    match sample {
        [] => Ok(None),
        [dt, file] => match dt.parse::<f64>() {
            Ok(v) if (1e-5..=1.0).contains(&v) => Ok(Some((v, PathBuf::from(file)))),
            _ => Err(format!(
                "--sample {dt}: DT is a period in seconds, 0.00001-1"
            )),
        },
        _ => Err("--sample needs DT and FILE".into()),
    }
}

impl Outputs {
    /// Checks the arguments and that every output can be written (before
    /// anything is loaded or created).
    pub fn validate(&self) -> Result<(), String> {
        let sample = sample_arg(&self.sample)?.map(|(_, p)| p);
        for (option, path) in [
            ("--toolpath", &self.toolpath),
            ("--report", &self.report),
            ("--plot", &self.plot),
            ("--sample", &sample),
            ("--log", &self.log),
            ("--stl", &self.stl),
            ("--png", &self.png),
        ] {
            if let Some(p) = path {
                check_writable(option, p).map_err(|e| e.to_string())?;
            }
        }
        if self.stock.is_none() {
            for (set, name) in [
                (self.tools.is_some(), "--tools"),
                (self.stl.is_some(), "--stl"),
                (self.png.is_some(), "--png"),
                (self.sim_res.is_some(), "--sim-res"),
            ] {
                if set {
                    return Err(format!("{name} needs --stock (the simulation's raw stock)"));
                }
            }
            return Ok(());
        }
        self.sim_res().map(|_| ())
    }

    fn sim_res(&self) -> Result<Option<f64>, String> {
        match &self.sim_res {
            None => Ok(None),
            Some(s) => match s.trim().parse::<f64>() {
                Ok(v) if v.is_finite() && (0.001..=10.0).contains(&v) => Ok(Some(v)),
                _ => Err(format!("--sim-res {s}: the cell size must be 0.001-10 mm")),
            },
        }
    }

    /// The simulation sink of `--stock`, checked against the machine (it
    /// runs before the report, which carries its section).
    pub fn sim(&self, profile: &Profile) -> Result<Option<SimSink>, String> {
        let Some(spec) = &self.stock else {
            return Ok(None);
        };
        let stock = Stock::parse(spec).map_err(|e| e.to_string())?;
        check_stock(&stock, profile).map_err(|e| e.to_string())?;
        let tools = match &self.tools {
            Some(p) => {
                let text =
                    std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
                kerf_sim::parse_tools(&text, profile.kind == MachineKind::Lathe)
                    .map_err(|e| format!("{}: {e}", p.display()))?
            }
            None => kerf_sim::ToolTable::default(),
        };
        let boxed = |p: &Option<PathBuf>| -> Result<Option<Box<dyn std::io::Write>>, String> {
            p.as_ref()
                .map(|p| create(p).map(|w| Box::new(w) as Box<dyn std::io::Write>))
                .transpose()
        };
        let res = self.sim_res()?;
        let sink = SimSink::new(stock, tools, res, boxed(&self.stl)?, boxed(&self.png)?)
            .map_err(|e| e.to_string())?;
        Ok(Some(sink))
    }

    /// The report sink: onto the `--report` file, or kept in memory only
    /// (the summary and `--json` read it).
    pub fn report(&self) -> Result<Report<Box<dyn Write>>, String> {
        let out: Box<dyn Write> = match &self.report {
            Some(p) => Box::new(create(p)?),
            None => Box::new(io::sink()),
        };
        Ok(Report::new(out))
    }

    /// Creates the files and the sinks of the other outputs.
    pub fn open(&self) -> Result<Vec<Box<dyn Sink>>, String> {
        let mut sinks: Vec<Box<dyn Sink>> = Vec::new();
        if let Some(p) = &self.toolpath {
            sinks.push(Box::new(toolpath(p)?));
        }
        if let Some((dt, p)) = sample_arg(&self.sample)? {
            sinks.push(Box::new(Sample::new(dt, create(&p)?)));
        }
        if let Some(p) = &self.log {
            sinks.push(Box::new(Log::new(create(p)?)));
        }
        if let Some(p) = &self.plot {
            sinks.push(Box::new(Plot::with_format(
                create(p)?,
                PlotFormat::of_path(p),
            )));
        }
        Ok(sinks)
    }
}
