//! Simulation throughput on generated moves (docs/benchmarks.md,
//! "Simulation"): `cargo bench -p kerf-sim --bench sim [CASE]`, each case
//! (benches/cases.rs) a fresh stock per iteration, moves per second as
//! criterion's throughput.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};

mod cases;

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("sim");
    g.sample_size(10);
    for case in cases::all() {
        g.throughput(Throughput::Elements(case.moves.len() as u64));
        g.bench_function(case.name, |b| {
            b.iter_batched_ref(
                case.make,
                |s| cases::run(s, &case.moves),
                BatchSize::PerIteration,
            )
        });
    }
    g.finish();
}

criterion_group!(sim_benches, benches);
criterion_main!(sim_benches);
