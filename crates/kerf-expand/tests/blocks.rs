//! The blocks written for hand-made event streams, worked out by hand from
//! the targets' word formats (000 / 001 / 002 for the Fanuc-family
//! controls, LinuxCNC's G-code reference for rs274ngc).

use kerf_canon::{
    ArcDir, Axis, Canon, Event, Feed, ModeChange, Motion, Plane, Pos, SpindleDir, SrcRef,
};
use kerf_expand::{Control, Expander, Spelling, Target};

const MILL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];
const LATHE: [Axis; 2] = [Axis::X, Axis::Z];

fn ev(line: u32, cmd: Canon) -> Event {
    Event {
        src: SrcRef {
            file: 0,
            line,
            col: 1,
        },
        tool: 1,
        cmd,
        prog: None,
    }
}

/// A motion whose machine position is the work position shifted by `off`.
fn mv(to: Pos, off: Pos) -> Motion {
    Motion {
        to,
        mto: std::array::from_fn(|i| to[i] + off[i]),
    }
}

fn p(x: f64, y: f64, z: f64) -> Pos {
    [x, y, z, 0.0, 0.0, 0.0]
}

/// The event blocks (header and trailer left out) for `events` on a
/// machine starting at work 0 with machine = work + `off`.
fn blocks(
    target: Target,
    control: Control,
    axes: &[Axis],
    off: Pos,
    events: &[Event],
) -> Vec<String> {
    let sp = Spelling::new(target, control);
    let header = sp.header().len();
    let start = [0.0; 6];
    let mut x = Expander::new(Vec::new(), sp, axes.to_vec(), start, off);
    x.start("part.nc").unwrap();
    for e in events {
        x.event(e, "/shop/progs/part.nc").unwrap();
    }
    let n = x.blocks() as usize;
    let text = String::from_utf8(x.finish().unwrap()).unwrap();
    text.lines()
        .skip(header)
        .take(n)
        .map(String::from)
        .collect()
}

#[test]
fn mill_moves_modal_words_and_arc_centres_from_the_start() {
    let o = [0.0; 6];
    let events = [
        ev(
            3,
            Canon::Rapid {
                m: mv(p(10.0, 0.0, 5.0), o),
                linear: true,
            },
        ),
        ev(
            4,
            Canon::Feed {
                m: mv(p(10.0, 0.0, -1.0), o),
                feed: Feed::PerMin(120.0),
            },
        ),
        // A quarter circle CCW about (10, 10) from (10, 0) to (20, 10):
        // I = 10 - 10 = 0, J = 10 - 0 = 10.
        ev(
            5,
            Canon::Arc {
                m: mv(p(20.0, 10.0, -1.0), o),
                center: p(10.0, 10.0, -1.0),
                mcenter: p(10.0, 10.0, -1.0),
                dir: ArcDir::Ccw,
                plane: Plane::XY,
                turns: 0,
                feed: Feed::PerMin(120.0),
            },
        ),
        ev(
            6,
            Canon::Feed {
                m: mv(p(20.0, 10.0, -1.0), o),
                feed: Feed::PerMin(80.5),
            },
        ),
    ];
    assert_eq!(
        blocks(Target::Fanuc, Control::Hx, &MILL, o, &events),
        [
            "G00 X10. Y0. Z5. (part.nc:3)",
            "G94 G01 Z-1. F120. (part.nc:4)",
            "G17 G03 X20. Y10. I0. J10. (part.nc:5)",
            // Nothing moves in the output's numbers: X still named.
            "G01 X20. F80.5 (part.nc:6)",
        ]
    );
    assert_eq!(
        blocks(Target::LinuxCnc, Control::Hx, &MILL, o, &events)[2],
        "G17 G3 X20. Y10. I0. J10. (part.nc:5)"
    );
}

#[test]
fn a_new_frame_is_set_with_g92_before_the_move() {
    // G54 at machine (-400, -250, -300); then the original switches to a
    // frame 50 mm further in X (G55) and moves only Y: the output sets
    // X to 10 - 50 = -40 at the current position, then moves.
    let g54 = p(-400.0, -250.0, -300.0);
    let g55 = p(-350.0, -250.0, -300.0);
    let events = [
        ev(
            2,
            Canon::Rapid {
                m: mv(p(10.0, 0.0, 0.0), g54),
                linear: true,
            },
        ),
        ev(
            4,
            Canon::Rapid {
                m: mv(p(-40.0, 5.0, 0.0), g55),
                linear: true,
            },
        ),
    ];
    // The machine starts at work 0 of G54.
    assert_eq!(
        blocks(Target::Fanuc, Control::Hx, &MILL, g54, &events),
        [
            "G00 X10. Y0. Z0. (part.nc:2)",
            "G92 X-40. (part.nc:4)",
            "Y5. (part.nc:4)",
        ]
    );
}

#[test]
fn puma_x_is_a_diameter_its_arc_i_a_radius() {
    let o = [0.0; 6];
    // Radius 20 → X40. diameter. Arc CW in ZX from (r20, z0) to (r25, z-5)
    // about (r20, z-5): I = 20 - 20 = 0, K = -5 - 0 = -5.
    let events = [
        ev(
            7,
            Canon::Feed {
                m: mv(p(20.0, 0.0, 0.0), o),
                feed: Feed::PerRev(0.2),
            },
        ),
        ev(
            8,
            Canon::Arc {
                m: mv(p(25.0, 0.0, -5.0), o),
                center: p(20.0, 0.0, -5.0),
                mcenter: p(20.0, 0.0, -5.0),
                dir: ArcDir::Cw,
                plane: Plane::ZX,
                turns: 0,
                feed: Feed::PerRev(0.2),
            },
        ),
        ev(
            9,
            Canon::Thread {
                m: mv(p(25.0, 0.0, -30.0), o),
                lead: 1.5,
            },
        ),
        ev(
            10,
            Canon::Tool {
                tool: 3,
                offset: 3,
                change: true,
            },
        ),
    ];
    assert_eq!(
        blocks(Target::Fanuc, Control::Puma, &LATHE, o, &events),
        [
            "G99 G01 X40. Z0. F0.2 (part.nc:7)",
            "G02 X50. Z-5. I0. K-5. (part.nc:8)",
            "G32 Z-30. F1.5 (part.nc:9)",
            "T0300 (part.nc:10)",
        ]
    );
    // LinuxCNC: radius mode (G8 in the header), G33 K.
    let l = blocks(Target::LinuxCnc, Control::Puma, &LATHE, o, &events);
    assert_eq!(l[0], "G95 G1 X20. Z0. F0.2 (part.nc:7)");
    assert_eq!(l[2], "G33 Z-30. K1.5 (part.nc:9)");
    assert_eq!(l[3], "T3 M6 (part.nc:10)");
}

#[test]
fn linuxcnc_m6_restarts_the_spindle_it_stops() {
    let events = [
        ev(
            1,
            Canon::Spindle {
                dir: SpindleDir::Ccw,
                rpm: 500.0,
                css: None,
            },
        ),
        ev(
            2,
            Canon::Tool {
                tool: 2,
                offset: 2,
                change: true,
            },
        ),
    ];
    let o = [0.0; 6];
    assert_eq!(
        blocks(Target::LinuxCnc, Control::Puma, &LATHE, o, &events),
        [
            "S500. M4 (part.nc:1)",
            "T2 M6 (part.nc:2)",
            "M4 (part.nc:2)"
        ]
    );
    // The PUMA's turret index leaves the spindle running.
    assert_eq!(
        blocks(Target::Fanuc, Control::Puma, &LATHE, o, &events),
        ["S500. M04 (part.nc:1)", "T0200 (part.nc:2)"]
    );
}

#[test]
fn hurco_thread_lead_follows_the_longer_axis_and_dwell_is_f() {
    let o = [0.0; 6];
    let events = [
        ev(
            1,
            Canon::Rapid {
                m: mv(p(10.0, 0.0, 2.0), o),
                linear: true,
            },
        ),
        // Facing thread: X moves 8 (radius), Z 0 → the lead is I.
        ev(
            2,
            Canon::Thread {
                m: mv(p(2.0, 0.0, 2.0), o),
                lead: 2.0,
            },
        ),
        ev(
            3,
            Canon::Thread {
                m: mv(p(2.0, 0.0, -20.0), o),
                lead: 2.0,
            },
        ),
        ev(
            4,
            Canon::Dwell {
                seconds: 1.5,
                revolutions: 0.0,
            },
        ),
        ev(
            5,
            Canon::Dwell {
                seconds: 0.0,
                revolutions: 3.0,
            },
        ),
    ];
    assert_eq!(
        blocks(Target::Fanuc, Control::Hurco, &LATHE, o, &events),
        [
            "G00 X20. Z2. (part.nc:1)",
            "G33 X4. I2. (part.nc:2)",
            "Z-20. K2. (part.nc:3)",
            "G94 G04 F1.5 (part.nc:4)",
            "G95 G04 F3. (part.nc:5)",
        ]
    );
}

#[test]
fn spindle_coolant_stops_and_end() {
    let events = [
        ev(
            1,
            Canon::Spindle {
                dir: SpindleDir::Cw,
                rpm: 1200.0,
                css: None,
            },
        ),
        ev(
            2,
            Canon::Coolant {
                mist: false,
                flood: true,
            },
        ),
        ev(3, Canon::Mode(ModeChange::SpindleClamp(2000.0))),
        ev(
            4,
            Canon::Spindle {
                dir: SpindleDir::Cw,
                rpm: 800.0,
                css: Some(150.0),
            },
        ),
        // CSS following the diameter: the same G96, nothing to write.
        ev(
            5,
            Canon::Spindle {
                dir: SpindleDir::Cw,
                rpm: 950.0,
                css: Some(150.0),
            },
        ),
        ev(
            6,
            Canon::Spindle {
                dir: SpindleDir::Stop,
                rpm: 950.0,
                css: Some(150.0),
            },
        ),
        ev(
            7,
            Canon::Coolant {
                mist: true,
                flood: false,
            },
        ),
        ev(8, Canon::Stop { optional: false }),
        ev(
            9,
            Canon::Aux {
                m: 19,
                name: "spindle orientation",
            },
        ),
        ev(10, Canon::End { code: 30 }),
    ];
    let o = [0.0; 6];
    assert_eq!(
        blocks(Target::Fanuc, Control::Puma, &LATHE, o, &events),
        [
            "S1200. M03 (part.nc:1)",
            "M08 (part.nc:2)",
            "G50 S2000. (part.nc:3)",
            "G96 S150. (part.nc:4)",
            "M05 (part.nc:6)",
            "M09 (part.nc:7)",
            "M07 (part.nc:7)",
            "M00 (part.nc:8)",
            "M19 (part.nc:9)",
            "M30 (part.nc:10)",
        ]
    );
    assert_eq!(
        blocks(Target::LinuxCnc, Control::Puma, &LATHE, o, &events),
        [
            "S1200. M3 (part.nc:1)",
            "M8 (part.nc:2)",
            "G96 D2000. S150. (part.nc:4)",
            "M5 (part.nc:6)",
            "M9 (part.nc:7)",
            "M7 (part.nc:7)",
            "M00 (part.nc:8)",
            "(M19 spindle orientation) (part.nc:9)",
            "M30 (part.nc:10)",
        ]
    );
}

#[test]
fn program_frame_per_target() {
    let sp = Spelling::new(Target::Fanuc, Control::Hx);
    let mut x = Expander::new(Vec::new(), sp, MILL.to_vec(), [0.0; 6], [0.0; 6]);
    x.start("dir/a(1).nc").unwrap();
    let text = String::from_utf8(x.finish().unwrap()).unwrap();
    assert_eq!(
        text,
        "%\nO0001 (KERF EXPAND OF a[1].nc TO fanuc)\nG21\nG17 G40 G49 G80 G90\n%\n"
    );
    let sp = Spelling::new(Target::LinuxCnc, Control::Hx);
    let mut x = Expander::new(Vec::new(), sp, MILL.to_vec(), [0.0; 6], [0.0; 6]);
    x.start("a.nc").unwrap();
    let text = String::from_utf8(x.finish().unwrap()).unwrap();
    assert_eq!(
        text,
        "G21 (KERF EXPAND OF a.nc TO linuxcnc)\nG17 G40 G49 G80 G90 G91.1\n"
    );
}
