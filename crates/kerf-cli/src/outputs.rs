//! Opens the output files of `kerf run` as kerf-control sinks.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use kerf_control::sinks::{Log, Plot, Report, Sample, Toolpath};
use kerf_control::Sink;

use crate::args::Outputs;

type Out = BufWriter<File>;

fn create(path: &Path) -> Result<Out, String> {
    File::create(path)
        .map(|f| BufWriter::with_capacity(1 << 16, f))
        .map_err(|e| format!("{}: {e}", path.display()))
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
    /// Checks the arguments (before anything is loaded).
    pub fn validate(&self) -> Result<(), String> {
        sample_arg(&self.sample).map(|_| ())
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
            sinks.push(Box::new(Toolpath::new(create(p)?)));
        }
        if let Some((dt, p)) = sample_arg(&self.sample)? {
            sinks.push(Box::new(Sample::new(dt, create(&p)?)));
        }
        if let Some(p) = &self.log {
            sinks.push(Box::new(Log::new(create(p)?)));
        }
        if let Some(p) = &self.plot {
            sinks.push(Box::new(Plot::new(create(p)?)));
        }
        Ok(sinks)
    }
}
