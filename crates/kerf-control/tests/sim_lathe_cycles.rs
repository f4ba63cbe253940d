//! The lathe cycles simulated from a bar through the runner, each part
//! checked against its profile and its volume by Pappus worked out by
//! hand from the program: G72 facing with G70, G73 pattern repeating
//! with G70 (001's example), G75 grooving (001's example), G92 and G76
//! threading as their passes, G74 drilling on the axis, a part-off.

use std::f64::consts::PI;

use kerf_control::sinks::SimSink;
use kerf_control::{Job, Sink};
use kerf_sim::{parse_tools, Model, SimReport, Stock};

struct Done {
    sink: SimSink,
    rep: SimReport,
}

fn run(program: &str, stock: &str, tools: &str) -> Done {
    let runner = Job::text("part.nc", program)
        .machine("puma-lathe")
        .load()
        .unwrap();
    let mut sink = SimSink::new(
        Stock::parse(stock).unwrap(),
        parse_tools(tools, true).unwrap(),
        None,
        None,
        None,
    )
    .unwrap();
    let outcome = runner.run(&mut [&mut sink as &mut dyn Sink]).unwrap();
    assert!(outcome.alarm.is_none(), "{:?}", outcome.alarm);
    let rep = sink.sim().report();
    assert_eq!(rep.collisions, 0, "{:?}", rep.events);
    Done { sink, rep }
}

impl Done {
    /// The radius intervals of material at z.
    fn at(&self, z: f64) -> Vec<(f64, f64)> {
        let Model::Lathe(s) = self.sink.sim().model() else {
            panic!("not a lathe")
        };
        s.intervals_at(z)
    }

    /// The outer radius at z (0 where nothing is left).
    fn outer(&self, z: f64) -> f64 {
        self.at(z).last().map_or(0.0, |iv| iv.1)
    }

    /// Asserts the outer radius against `want` at z from `a` to `b` every
    /// `step`, within `tol`.
    fn profile(&self, a: f64, b: f64, step: f64, tol: f64, want: impl Fn(f64) -> f64) {
        let n = ((b - a) / step).round() as usize;
        for i in 0..=n {
            let z = a + (b - a) * i as f64 / n as f64;
            let (got, w) = (self.outer(z), want(z));
            assert!((got - w).abs() <= tol, "z {z}: r {got}, want {w}");
        }
    }
}

fn close(got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "{got} vs {want} ± {tol}");
}

/// π ∫ r² dz over a length `l` where r runs linearly from `a` to `b`.
fn frustum(a: f64, b: f64, l: f64) -> f64 {
    PI * l * (a * a + a * b + b * b) / 3.0
}

/// A sharp 80° OD insert (tip 3, bisector 45°: edges at 5° and 85°).
const SHARP: &str = "[tool.1]\nnose_radius=0\ntip=3\n";

#[test]
fn g72_facing_and_g70_leave_the_programmed_face() {
    // The shape from (r 42, z -10): r 40 at z -10, a cone to (30, -6),
    // the cylinder r 30 to z -2, a cone to (10, 0); G72 leaves W0.2, G70
    // finishes to the shape. From a bar r 40 with its face at z 0.
    let d = run(
        "G97 S500 M03\nT0101\nG00 X84. Z2.\nG72 W2. R0.5\nG72 P10 Q50 U0 W0.2 F0.2\n\
         N10 G00 Z-10.\nN20 G01 X80.\nN30 X60. Z-6.\nN40 Z-2.\nN50 X20. Z0.\n\
         G70 P10 Q50\nG00 X100. Z50.\nM30\n",
        "bar:80,100",
        SHARP,
    );
    let shape = |z: f64| {
        if z < -10.0 {
            40.0
        } else if z < -6.0 {
            40.0 - 2.5 * (z + 10.0)
        } else if z < -2.0 {
            30.0
        } else {
            30.0 - 10.0 * (z + 2.0)
        }
    };
    // Exact on these lines: the sharp tip traces them.
    d.profile(-15.0, -0.01, 0.0497, 1e-6, shape);
    // The face inside r 10 is the bar's own.
    assert_eq!(d.at(-0.01)[0].0, 0.0);
    let want =
        PI * 1600.0 * 90.0 + frustum(40.0, 30.0, 4.0) + PI * 900.0 * 4.0 + frustum(30.0, 10.0, 2.0);
    close(d.rep.remaining_mm3, want, 1e-3);
}

#[test]
fn g73_pattern_repeating_and_g70_leave_001s_shape() {
    // 001's G73 example (its facing pass at Z0 comes by rapid to X35 Z0,
    // so the bar's face must be at Z0: a face at Z1 is a rapid into the
    // stock), then
    // the shape r 10 to Z-10, a cone to (20, -20), G02 R10 to (30, -30)
    // (centre (r 30, z -20): r = 30 - √(100 - (z + 20)²)), and X70.
    let prog = "N10 G50 S2000 T0300\nG96 S200 M03\nG00 X35.0 Z5.0 T0303\nZ0\nG01 X-1.6 F0.2\n\
         G00 X70.0 Z10.0\nG73 U3.0 W2.0 R2\nG73 P12 Q16 U0.5 W0.1 F0.25\nN12 G00 X20. Z2.\n\
         N13 G01 Z-10.\nN14 X40. Z-20.\nN15 G02 X60. Z-30. R10.\nN16 G01 X70.\n\
         G70 P12 Q16\nG00 X100. Z50.\nM30\n";
    // G73 is for near-net blanks: its passes (3 mm of stock in X) do not
    // clear a bar. With 8 mm edges the insert cannot reach the bar's OD
    // above the cone's foot: at (z -19.9, r 30) the nearest tip, on the
    // arc at (-25, 21.34), is 13.8 mm away along the insert's bisector,
    // whose far side is at 8 cos 40° = 6.1 mm.
    let d = run(prog, "bar:70,100", "[tool.3]\nnose_radius=0\ntip=3\n");
    assert_eq!(d.outer(-19.9), 35.0);
    // With 40 mm edges the insert's body sweeps all the bar above the
    // shape (its edges at 5° and 85° stay outside the shape on the whole
    // path: the path is convex toward them).
    let d = run(
        prog,
        "bar:70,100",
        "[tool.3]\nnose_radius=0\ntip=3\nedge_length=40\n",
    );
    let shape = |z: f64| {
        if z > -10.0 {
            10.0
        } else if z > -20.0 {
            -z
        } else if z > -30.0 {
            30.0 - (100.0 - (z + 20.0).powi(2)).sqrt()
        } else {
            35.0
        }
    };
    // The arc is chorded at 0.5 µm; its slope reaches 1 at z -27.1, so
    // along r the error stays below 1 µm from z -29.
    d.profile(-20.0, -0.01, 0.0497, 1e-6, shape);
    d.profile(-29.0, -20.0, 0.0497, 1e-3, shape);
    // By hand: π [100·10 + ∫ z² (-20..-10) + ∫ (30 - √(100 - u²))² (u
    // -10..0) + 35²·70]; the middle term is 10·1000 - 60·(π 100 / 4) -
    // 1000/3; the bar's 70 mm below Z-30.
    let arc = 10.0 * 1000.0 - 60.0 * (PI * 100.0 / 4.0) - 1000.0 / 3.0;
    let want = PI * (1000.0 + (8000.0 - 1000.0) / 3.0 + arc + 1225.0 * 70.0);
    // The chords lie inside the arc's circle, on the part's side of the
    // arc: they leave at most 0.5 µm over its 15.7 mm at radii up to 30
    // (found: 0.77 mm³, about 2/3 of that, as the mean of a sagitta).
    let chords = 0.5e-3 * (PI * 10.0 / 2.0) * 2.0 * PI * 30.0;
    let got = d.rep.remaining_mm3;
    assert!(
        (want..=want + chords).contains(&got),
        "{got} vs {want} + {chords}"
    );
}

#[test]
fn g75_cuts_three_grooves_of_the_blades_width() {
    // 001's G75 example: grooves from X82 Z-60 to X60 Z-20, 20 mm apart,
    // 3 mm pecks; a 3 mm blade programmed at its -Z corner.
    let d = run(
        "N10 G50 S500 T0100\nG97 S280 M03\nG00 X90.0 Z1.0 T0101\nX82.0 Z-60.0\n\
         G75 R1.0\nG75 X60.0 Z-20.0 P3000 Q20000 F0.1\nG00 X90.0\nX200.0 Z200.0 T0100\nM30\n",
        "bar:80,100",
        "[tool.1]\nkind=\"groove\"\nwidth=3\ndepth=20\nnose_radius=0\ntip=3\n",
    );
    close(d.rep.removed_mm3, 3.0 * PI * (1600.0 - 900.0) * 3.0, 1e-3);
    for z0 in [-60.0, -40.0, -20.0] {
        close(d.outer(z0 + 1.5), 30.0, 1e-6);
        close(d.outer(z0 + 3.01), 40.0, 1e-6);
        close(d.outer(z0 - 0.01), 40.0, 1e-6);
    }
}

/// A sharp 60° threading insert pointing to -X.
const THREAD: &str = "[tool.1]\nnose_radius=0\nangle=60\nbisector=90\nedge_length=3\n";

#[test]
fn g92_threading_passes_turn_the_thread_to_its_root() {
    // Four G92 passes to the root Ø27.4 at Z-30 on a Ø30 bar: in the
    // model of revolution the passes leave the root's cylinder r 13.7,
    // and past Z-30 the insert's left flank (60°: r rises √3 per mm of
    // -z) a cone up to r 15.
    let d = run(
        "G97 S600 M03\nT0101\nG00 X34. Z5.\nG92 X29.2 Z-30. F2.\nX28.6\nX28.0\nX27.4\n\
         G00 X100. Z50.\nM30\n",
        "bar:30,100",
        THREAD,
    );
    let s3 = 3f64.sqrt();
    let shape = |z: f64| {
        if z > -30.0 {
            13.7
        } else {
            (13.7 + s3 * (-30.0 - z)).min(15.0)
        }
    };
    d.profile(-32.0, -0.01, 0.0497, 1e-6, shape);
    // Removed: the shell r 13.7..15 over 30 mm, and the flank's ring 2π ∫
    // r (r - 13.7)/√3 dr for r 13.7..15.
    let (a, h) = (13.7, 1.3);
    let ring = 2.0 * PI * (a * h * h / 2.0 + h * h * h / 3.0) / s3;
    close(d.rep.removed_mm3, PI * (225.0 - a * a) * 30.0 + ring, 1e-3);
}

#[test]
fn g76_threading_passes_and_their_run_out() {
    // 001's G76 format: root Ø27.4, k 1.3, run-out 1.0·L = 2 mm at 45°
    // (kerf-interp's g76_every_pass gives each pass). The last passes run
    // at r 13.7 to Z-28 and pull out along r = 13.7 + (-28 - z), which
    // leaves the bar's r 15 at Z-29.3; the flanks are steeper than the
    // run-out, so it is the profile.
    let d = run(
        "G97 S600 M03\nT0101\nG00 X34. Z5.\nG76 P021060 Q100 R0.05\n\
         G76 X27.4 Z-30. P1300 Q500 F2.\nG00 X100. Z50.\nM30\n",
        "bar:30,100",
        THREAD,
    );
    let shape = |z: f64| {
        if z > -28.0 {
            13.7
        } else {
            (13.7 + (-28.0 - z)).min(15.0)
        }
    };
    d.profile(-31.0, -0.01, 0.0497, 1e-6, shape);
    let want = PI * (225.0 - 13.7 * 13.7) * 28.0 + (PI * 225.0 * 1.3 - frustum(13.7, 15.0, 1.3));
    close(d.rep.removed_mm3, want, 1e-3);
}

#[test]
fn g74_pecks_a_drilled_hole_on_the_axis() {
    // A Ø10 118° drill pecking 5 mm at a time to Z-30 from a face at Z0:
    // the hole's cylinder to the point's shoulder and the point's cone,
    // h = 5 / tan 59°.
    let d = run(
        "G97 S800 M03\nT0202\nG00 X0. Z2.\nG74 R1.0\nG74 Z-30. Q5000 F0.1\nG00 Z50.\n\
         X100.\nM30\n",
        "bar:50,100",
        "[tool.2]\nkind=\"drill\"\ndiameter=10\npoint_angle=118\n",
    );
    let h = 5.0 / 59f64.to_radians().tan();
    close(
        d.rep.removed_mm3,
        PI * 25.0 * (30.0 - h) + PI * 25.0 * h / 3.0,
        1e-3,
    );
    // The bore's wall and the point's cone.
    assert_eq!(d.at(-10.0), vec![(5.0, 25.0)]);
    let z = -30.0 + h / 2.0;
    let iv = d.at(z);
    close(iv[0].0, 2.5, 1e-6);
    assert_eq!(d.at(-30.01), vec![(0.0, 25.0)]);
}

#[test]
fn a_part_off_past_the_centre_separates_the_part() {
    // A 3 mm blade (0.2 corners) programmed at its -Z corner at Z-43 feeds
    // from Ø52 to X-1 (0.5 past the axis): the slice z -43..-40 is gone.
    let d = run(
        "G97 S300 M03\nT0505\nG00 X52. Z-43.\nG01 X-1. F0.05\nG00 X60.\nZ50.\nM30\n",
        "bar:50,100",
        "[tool.5]\nkind=\"groove\"\nwidth=3\ndepth=30\nnose_radius=0.2\ntip=3\n",
    );
    close(d.rep.removed_mm3, PI * 625.0 * 3.0, 1e-3);
    assert!(d.at(-41.5).is_empty());
    assert_eq!(d.at(-39.99), vec![(0.0, 25.0)]);
    assert_eq!(d.at(-43.01), vec![(0.0, 25.0)]);
    let Model::Lathe(s) = d.sink.sim().model() else {
        panic!()
    };
    // Two pieces: the part and the bar's remnant.
    assert_eq!(s.outline().len(), 2);
}
