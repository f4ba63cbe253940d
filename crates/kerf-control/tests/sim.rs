//! The simulation sink on real runs: the manual's G71 cycle from a bar
//! leaves the programmed shape plus its finishing allowance; a milled slot
//! and a rapid into the stock through the runner; stocks that do not suit
//! the machine.

use std::f64::consts::PI;

use kerf_control::sinks::sim::check_stock;
use kerf_control::sinks::{Report, SimSink};
use kerf_control::{Job, Sink};
use kerf_sim::{parse_tools, Model, Stock};

/// 001's G71 format with the shape of kerf-interp's lathe_mrc tests (no
/// G70): roughing and the semi-finish pass leave the shape shifted by
/// (U/2, W) = (0.2, 0.1).
const G71: &str = "G97 S500 M03
T0101
G00 X82. Z2.
G71 U2. R0.5
G71 P10 Q60 U0.4 W0.1 F0.25
N10 G00 X30.
N20 G01 Z-20. F0.1
N30 X40. Z-30.
N40 G02 X60. Z-40. R10.
N50 G01 X78.
N60 Z-60.
G00 X100. Z50.
M30
";

/// The shifted shape's radius at z (from the program, by hand).
fn shape(z: f64) -> f64 {
    if z > -19.9 {
        15.2
    } else if z > -29.9 {
        15.2 + (-19.9 - z) / 2.0
    } else if z > -39.9 {
        30.2 - (100.0 - (z + 29.9).powi(2)).sqrt()
    } else if z > -59.9 {
        39.2
    } else {
        40.0
    }
}

fn run_sim(machine: &str, program: &str, stock: &str, tools: &str) -> (SimSink, serde_json::Value) {
    let runner = Job::text("part.nc", program)
        .machine(machine)
        .load()
        .unwrap();
    let lathe = machine != "hx-mc";
    let mut sim = SimSink::new(
        Stock::parse(stock).unwrap(),
        parse_tools(tools, lathe).unwrap(),
        None,
        None,
        None,
    )
    .unwrap();
    let mut out = Vec::new();
    {
        let mut rep = Report::new(&mut out).with_sim(sim.handle());
        let outcome = runner
            .run(&mut [&mut sim as &mut dyn Sink, &mut rep])
            .unwrap();
        assert!(outcome.alarm.is_none());
    }
    (sim, serde_json::from_slice(&out).unwrap())
}

#[test]
fn the_g71_cycle_from_a_bar_leaves_the_shape_plus_the_allowance() {
    let (sim, rep) = run_sim(
        "puma-lathe",
        G71,
        "bar:80,100",
        "[tool.1]\nnose_radius=0\ntip=3\n",
    );
    let Model::Lathe(s) = sim.sim().model() else {
        panic!()
    };
    // The profile every 0.25 mm (and just off its corners): exact on the
    // lines; on the arc (split in chords of 0.5 µm) within 0.5 µm of the
    // circle along its normal.
    let zs = (1..400).map(|i| -0.25 * i as f64 + 0.0123);
    for z in zs {
        let got = s.intervals_at(z).last().map_or(0.0, |iv| iv.1);
        if (-39.9..-29.9).contains(&z) {
            let d = (z + 29.9).hypot(got - 30.2);
            assert!(
                (10.0 - 0.5e-3 - 1e-6..=10.0 + 1e-6).contains(&d),
                "z {z}: {got}, {d} from the centre"
            );
        } else if (z + 59.9).abs() > 0.1 {
            assert!(
                (got - shape(z)).abs() < 1e-6,
                "z {z}: {got} vs {}",
                shape(z)
            );
        }
    }
    // Remaining volume: pi ∫ r(z)² dz from -100 to 0 (Simpson, 200,000 steps).
    let n = 200_000;
    let h = 100.0 / n as f64;
    let mut acc = 0.0;
    for i in 0..=n {
        let z = -100.0 + i as f64 * h;
        let w = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        acc += w * shape(z).powi(2);
    }
    // Where the last pass stops at Z-59.9 under the bar's r 40, the
    // insert's leading edge (85° from +Z: an 80° insert with its bisector
    // at 45°) leaves a ring: r from 39.2 to 40, z up to (r - 39.2) cot 85°
    // above -59.9: 2 pi ∫ r (r - 39.2) cot 85° dr.
    let cot = 1.0 / 85f64.to_radians().tan();
    let ring = 2.0
        * PI
        * cot
        * ((40f64.powi(3) - 39.2f64.powi(3)) / 3.0
            - 39.2 * (40f64.powi(2) - 39.2f64.powi(2)) / 2.0);
    let want = PI * acc * h / 3.0 + ring;
    let sim_rep = &rep["sim"];
    let got = sim_rep["remaining_mm3"].as_f64().unwrap();
    // The arc's chords (0.5 µm) leave at most 0.5e-3 × its 2 pi 25 × 15.7
    // mm² of surface: 1.3 mm³; the polygons are otherwise exact.
    assert!((got - want).abs() < 1.5, "{got} vs {want}");
    assert_eq!(sim_rep["events"].as_array().unwrap().len(), 0, "{sim_rep}");
    assert_eq!(sim_rep["collisions"], 0);
}

#[test]
fn a_rapid_into_the_block_through_the_runner() {
    let prog =
        "G90 G54 G17\nT1 M06\nG43 H1 Z50.\nS2000 M03\nG00 X20. Y50.\nG00 Z5.\nG01 Z-2. F200\n\
                G01 X80. F500\nG00 Z50.\nG00 X50. Y20.\nG00 Z-1.\nM30\n";
    let (_, rep) = run_sim(
        "hx-mc",
        prog,
        "box:0,0,-20,100,100,0",
        "[tool.1]\nkind=\"flat\"\ndiameter=10\n",
    );
    let s = &rep["sim"];
    let ev = s["events"].as_array().unwrap();
    assert_eq!(ev.len(), 1, "{s}");
    assert_eq!(ev[0]["kind"], "rapid_into_stock");
    assert_eq!(ev[0]["line"], 11);
    assert_eq!(ev[0]["file"], "part.nc");
    assert_eq!(ev[0]["at"][0], 50.0);
    assert_eq!(ev[0]["at"][1], 20.0);
    // The spindle is running and the slot is at feed: nothing else.
    assert_eq!(s["collisions"], 1);
    assert!(s["removed_mm3"].as_f64().unwrap() > 1200.0);
}

#[test]
fn a_stock_must_suit_the_machine() {
    let mill = kerf_interp::Profile::builtin("hx-mc").unwrap();
    let lathe = kerf_interp::Profile::builtin("puma-lathe").unwrap();
    let bar = Stock::parse("bar:50,100").unwrap();
    let e = check_stock(&bar, &mill).unwrap_err().to_string();
    assert!(e.contains("lathe stock"), "{e}");
    let b = Stock::parse("box:0,0,-10,100,100,0").unwrap();
    assert!(check_stock(&b, &lathe)
        .unwrap_err()
        .to_string()
        .contains("machining center stock"));
    assert!(check_stock(&b, &mill).is_ok());
    // G54 puts X0 at machine -400 of a -800..0 travel: X up to 500 is out.
    let big = Stock::parse("box:0,0,-10,500,100,0").unwrap();
    let e = check_stock(&big, &mill).unwrap_err();
    assert_eq!(
        e.to_string(),
        "--stock: X 0..500 is machine -400..100, outside the X travel -800..0"
    );
}

#[test]
fn a_g81_cycle_drills_three_holes_with_their_points() {
    let prog = "G90 G54 G17\nT1 M06\nG43 H1 Z50.\nS1000 M03\nG00 X10. Y10.\n\
                G99 G81 X10. Y10. Z-10. R2. F100\nX30.\nX50.\nG80\nG00 Z50.\nM30\n";
    let runner = Job::text("drill.nc", prog).machine("hx-mc").load().unwrap();
    let tools = parse_tools(
        "[tool.1]\nkind=\"drill\"\ndiameter=8\npoint_angle=118\n",
        false,
    )
    .unwrap();
    let mut sim = SimSink::new(
        Stock::parse("box:0,0,-20,60,20,0").unwrap(),
        tools,
        Some(0.02),
        None,
        None,
    )
    .unwrap();
    let outcome = runner.run(&mut [&mut sim as &mut dyn Sink]).unwrap();
    assert!(outcome.alarm.is_none());
    let rep = sim.sim().report();
    // Per hole: the cylinder to the point's shoulder and the point's cone,
    // h = 4 / tan 59°.
    let hp = 4.0 / 59f64.to_radians().tan();
    let want = 3.0 * (PI * 16.0 * (10.0 - hp) + PI * 16.0 * hp / 3.0);
    // Cells in or out by their centre: perimeter × half diagonal × depth per hole.
    let bound = 3.0 * (2.0 * PI * 4.0 * 0.02 * std::f64::consts::FRAC_1_SQRT_2 * 10.0);
    assert!(
        (rep.removed_mm3 - want).abs() <= bound,
        "{} vs {want} ± {bound}",
        rep.removed_mm3
    );
    assert!(rep.events.is_empty(), "{:?}", rep.events);
}
