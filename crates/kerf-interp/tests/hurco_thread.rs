//! Hurco G78 threading (002 Tables 5-13 and the four sample thread
//! programs). Pass depths are worked out by hand in the comments (and, for
//! long series, by a closed formula in the test); positions by f64
//! trigonometry from the cycle's geometry as docs/dialects.md describes it:
//! per pass rapid in-feed (or A chase-in), thread to the pull-out point,
//! rapid pull-out (or C chase-out), rapid back to the start point.
mod common;
use common::*;
use kerf_canon::Canon;
use kerf_interp::Run;

const IN: f64 = 25.4;

/// (kind, x, z) of every move in inches (X a radius), rounded to 1e-6 in.
fn path(r: &Run) -> Vec<(&'static str, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "rapid",
                Canon::Feed { .. } => "feed",
                Canon::Thread { .. } => "thread",
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((k, round(m.to[0] / IN), round(m.to[2] / IN)))
        })
        .collect()
}

fn leads(r: &Run) -> Vec<f64> {
    r.events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Thread { lead, .. } => Some(lead),
            _ => None,
        })
        .collect()
}

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() < 2e-6
}

/// Asserts a move list equals the expected one (inches, 2e-6 in).
fn assert_path(got: &[(&str, f64, f64)], want: &[(&str, f64, f64)]) {
    assert_eq!(got.len(), want.len(), "move count: got {got:?}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            g.0 == w.0 && near(g.1, w.1) && near(g.2, w.2),
            "move {i}: got {g:?}, want {w:?}"
        );
    }
}

/// The moves of one straight pass without A/C: rapid in-feed at the start
/// Z, thread to the end, rapid out to the clearance, rapid back.
fn straight_pass(r: f64, z0: f64, z_end: f64, clear: f64) -> Vec<(&'static str, f64, f64)> {
    vec![
        ("rapid", r, z0),
        ("thread", r, z_end),
        ("rapid", clear, z_end),
        ("rapid", clear, z0),
    ]
}

const HEAD: &str = "G70 G90 M03 S120\n";

#[test]
fn straight_od_thread_sample() {
    // 002 "Straight OD Thread": G78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02 R3.
    // Major radius .9 + .2 = 1.1; clearance U .1 -> 1.2; start Z = K + W =
    // 2.1; end Z1.2 (C0: at the major radius too). Finish 2 x .02, so the
    // rough depth is .2 - .04 = .16: n = ceil(2*.16/(.04+.03)) = ceil(4.57)
    // = 5 passes, first 2*.16/5 - .03 = .034, falling by .001 to .030:
    // cumulative .034 .067 .099 .130 .160, then finish .18 .20, then 3
    // spring passes at .20. Radii = 1.1 - depth.
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 Z4.1\nG78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02 R3\nM30\n"),
    );
    ok(&r);
    let p = path(&r);
    // Power-on X is the reference, 250 mm radius.
    let x0 = 250.0 / IN;
    let mut want = vec![("rapid", x0, 4.1), ("rapid", 1.2, 2.1)];
    for d in [
        0.034, 0.067, 0.099, 0.130, 0.160, 0.18, 0.20, 0.20, 0.20, 0.20,
    ] {
        want.extend(straight_pass(1.1 - d, 2.1, 1.2, 1.2));
    }
    assert_path(&p, &want);
    // Lead .15 in/rev = 3.81 mm.
    assert!(leads(&r).iter().all(|&l| near(l, 3.81)));
    assert_eq!(leads(&r).len(), 10);
}

#[test]
fn multi_letter_names_give_the_same_thread() {
    let single = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 Z4.1\nG78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02 R3\nM30\n"),
    );
    let long = run_on(
        "hurco-lathe",
        &format!(
            "{HEAD}G0 Z4.1\nG78 minR.9 depth.2 ZEnd1.2 ZStart2 pitch.15 dStart.04 dEnd.03 \
             nFin2 dFin.02 nSpring3\nM30\n"
        ),
    );
    ok(&long);
    assert_eq!(path(&single), path(&long));
    // minD is a diameter: minD1.8 = X.9 (not affected by G07/G08).
    let dia = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 Z4.1\nG78 minD1.8 J.2 T.8 K2 tpi8 D.04 E.03 P2 L.02 R3\nM30\n"),
    );
    ok(&dia);
    // T.8 from K2 towards -Z ends at Z1.2: the same passes; tpi8 (= F-8)
    // is a lead of 1/8 in = 3.175 mm.
    assert_eq!(path(&single), path(&dia));
    assert!(leads(&dia).iter().all(|&l| (l - 3.175).abs() < 1e-9));
}

#[test]
fn lead_in_lead_out_sample() {
    // 002 "Straight OD Thread with Lead In/Lead Out Angles":
    // G78 X.9 J.6 Z1.2 K2 A30 C5 F.15 D.04 E.03 P2 L.02.
    // Major 1.5, clearance 1.6, start point (1.6, 2.1). Rough .6 - .04 =
    // .56: n = ceil(1.12/.07) = 16, first 1.12/16 - .03 = .04 = D, the
    // cuts fall by .01/15 to .03; then finish .58, .60 (no R). Z1.2 is
    // the end at the clearance: the pull-out line at 5° meets the major
    // radius at H = 1.2 + .1 tan5°. Per pass at depth c: chase-in from
    // (1.6, 2.1) to (1.5 - c, 2.1 - (.1 + c) tan30°), thread to
    // (1.5 - c, H - c tan5°), chase-out to (1.6, 1.2), rapid to (1.6, 2.1).
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X4.1 Z2.5\nG78 X.9 J.6 Z1.2 K2 A30 C5 F.15 D.04 E.03 P2 L.02\nM30\n"),
    );
    ok(&r);
    let (ta, tc) = (30f64.to_radians().tan(), 5f64.to_radians().tan());
    let h = 1.2 + 0.1 * tc;
    let step = 0.01 / 15.0;
    let mut depths: Vec<f64> = (1..=16)
        .map(|k| {
            let k = k as f64;
            0.04 * k - step * k * (k - 1.0) / 2.0
        })
        .collect();
    assert!((depths[15] - 0.56).abs() < 1e-12);
    depths.extend([0.58, 0.60]);
    // G0 X4.1 in the power-on G08 (diameter): radius 2.05.
    let mut want = vec![("rapid", 2.05, 2.5), ("rapid", 1.6, 2.1)];
    for c in depths {
        want.push(("thread", 1.5 - c, 2.1 - (0.1 + c) * ta));
        // The pull-out line through (1.5, H) reaches depth c earlier along
        // the thread (the thread runs towards -Z): z = H + c tan5°.
        want.push(("thread", 1.5 - c, h + c * tc));
        want.push(("thread", 1.6, 1.2));
        want.push(("rapid", 1.6, 2.1));
    }
    let p = path(&r);
    assert_path(&p, &want);
    // The main thread move's lead is F; the steep chase-in (X longer than
    // Z) carries the lead along X: .15 * dx/dz = .15 / tan30° for the
    // first pass (dx = .14, dz = .14 tan30°).
    let l = leads(&r);
    assert!((l[0] - 0.15 * IN / ta).abs() < 1e-9, "{}", l[0]);
    assert!((l[1] - 0.15 * IN).abs() < 1e-9);
}

#[test]
fn tapered_od_sample() {
    // 002 "Tapered OD Thread": G78 X.9 J.6 B14.7 Z1.2 K4 F.375 D.1 E.08
    // P2 L.02 R3, after G0Z4.1. Major radius at K4: 1.5. Rough .56: n =
    // ceil(1.12/.18) = 7, first 1.12/7 - .08 = .08 = E: 7 equal cuts of
    // .08; then finish .58 .60 and 3 spring passes at .60 (12 passes).
    // Every line is parallel to the taper: radius + tan(14.7°) * (K - z);
    // the start point is W = .1 before K (z 4.1: -.1 along the thread).
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0Z4.1\nG78 X.9 J.6 B14.7 Z1.2 K4 F.375 D.1 E.08 P2 L.02 R3\nM30\n"),
    );
    ok(&r);
    let tb = 14.7f64.to_radians().tan();
    let at = |rad: f64, z: f64| rad + (4.0 - z) * tb;
    let mut want = vec![("rapid", 250.0 / IN, 4.1), ("rapid", at(1.6, 4.1), 4.1)];
    let mut depths: Vec<f64> = (1..=7).map(|k| 0.08 * k as f64).collect();
    depths.extend([0.58, 0.60, 0.60, 0.60, 0.60]);
    for c in depths {
        want.push(("rapid", at(1.5 - c, 4.1), 4.1));
        want.push(("thread", at(1.5 - c, 1.2), 1.2));
        want.push(("rapid", at(1.6, 1.2), 1.2));
        want.push(("rapid", at(1.6, 4.1), 4.1));
    }
    assert_path(&path(&r), &want);
    assert!(leads(&r).iter().all(|&l| near(l, 0.375 * IN)));
}

#[test]
fn straight_id_sample() {
    // 002 "Straight ID Thread": G78 X.9 J-.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02.
    // X and J of opposite signs: ID. The first pass is at X+J = .7, the
    // passes go outwards to .9; clearance .7 - .1 = .6. Depths as in the
    // straight OD sample (rough .16 in 5 cuts from .034 to .030, finish .18
    // .20), no spring passes.
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 Z4.1\nG78 X.9 J-.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02\nM30\n"),
    );
    ok(&r);
    let mut want = vec![("rapid", 250.0 / IN, 4.1), ("rapid", 0.6, 2.1)];
    for d in [0.034, 0.067, 0.099, 0.130, 0.160, 0.18, 0.20] {
        want.extend(straight_pass(0.7 + d, 2.1, 1.2, 0.6));
    }
    assert_path(&path(&r), &want);
}

#[test]
fn figure_23_and_24_depths() {
    // Figure 23: G78 X1.05 J.45 D.1 E.05: 2*.45/.15 = 6 cuts .1 .09 .08
    // .07 .06 .05 (cumulative .1 .19 .27 .34 .40 .45).
    // Figure 24 (L.01 P3): rough .42, n = ceil(.84/.15) = 6, first
    // .84/6 - .05 = .09, cuts .09 .082 .074 .066 .058 .05 (cumulative .09
    // .172 .246 .312 .370 .42), then .43 .44 .45.
    let radii = |extra: &str| -> Vec<f64> {
        let r = run_on(
            "hurco-lathe",
            &format!("{HEAD}G0 X3 Z2\nG78 X1.05 J.45 K1 H-1 F.1 D.1 E.05{extra}\nM30\n"),
        );
        ok(&r);
        path(&r)
            .iter()
            .filter(|m| m.0 == "thread")
            .map(|m| round(1.5 - m.1))
            .collect()
    };
    assert_eq!(radii(""), vec![0.1, 0.19, 0.27, 0.34, 0.40, 0.45]);
    assert_eq!(
        radii(" L.01 P3"),
        vec![0.09, 0.172, 0.246, 0.312, 0.37, 0.42, 0.43, 0.44, 0.45]
    );
    // P without L: no finish passes, P + R spring passes at full depth.
    let v = radii(" P2 R1");
    assert_eq!(v.len(), 6 + 3);
    assert!(v[6..].iter().all(|&d| d == 0.45));
    // L without P: one finish pass. Rough .44: ceil(.88/.15) = 6 cuts,
    // first .88/6 - .05 = .096667; last rough .44, then .45.
    let v = radii(" L.01");
    assert_eq!(v.len(), 7);
    assert!((v[0] - (0.88 / 6.0 - 0.05)).abs() < 1e-6);
    assert_eq!(&v[5..], &[0.44, 0.45]);
}

#[test]
fn constant_volume_passes() {
    // V1: cumulative depth D*sqrt(k): J.1 D.04: .04, .056569, .069282,
    // .08, .089443, .09798, then .1 (sqrt(7)*.04 = .10583 > .1).
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X3 Z2\nG78 X1 J.1 K1 Z0 F.1 D.04 V1\nM30\n"),
    );
    ok(&r);
    let d: Vec<f64> = path(&r)
        .iter()
        .filter(|m| m.0 == "thread")
        .map(|m| 1.1 - m.1)
        .collect();
    let want = [
        0.04,
        0.04 * 2f64.sqrt(),
        0.04 * 3f64.sqrt(),
        0.08,
        0.04 * 5f64.sqrt(),
        0.04 * 6f64.sqrt(),
        0.1,
    ];
    assert_eq!(d.len(), want.len());
    for (a, b) in d.iter().zip(want) {
        assert!((a - b).abs() < 2e-6, "{a} {b}");
    }
}

#[test]
fn multiple_starts_and_start_angle() {
    // Q3: every depth cut at 0°, 120°, 240° (messages before the thread
    // move of the 120° and 240° starts). J.1 D.05: ceil(.2/.1) = 2 cuts of
    // .05 -> 2 depths x 3 starts = 6 thread moves.
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X3 Z2\nG78 X1 J.1 K1 Z0 F.3 D.05 Q3\nM30\n"),
    );
    ok(&r);
    let msgs: Vec<String> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Message(m) => Some(m.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(
        msgs,
        vec![
            "thread start angle 120",
            "thread start angle 240",
            "thread start angle 120",
            "thread start angle 240"
        ]
    );
    assert_eq!(leads(&r).len(), 6);
    // one start at 170°.
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X3 Z2\nG78 X1 J.1 K1 Z0 F.3 D.05 Q-170\nM30\n"),
    );
    ok(&r);
    let n = r
        .events
        .iter()
        .filter(|e| matches!(&e.cmd, Canon::Message(m) if m == "thread start angle 170"))
        .count();
    assert_eq!(n, 2);
}

#[test]
fn face_thread() {
    // M1: thread along X from I2 to X.5 (end at the Z clearance), final
    // pass at Z-.1, J.1 (start depth Z0), W .1 depth clearance (Z .1), U
    // .1 before the start (X 2.1). D=E=.05: 2 cuts of .05.
    let r = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X3 Z1\nG78 M1 Z-.1 J.1 I2 X.5 F.1 D.05\nM30\n"),
    );
    ok(&r);
    // G0 X3 in the power-on G08 (diameter): radius 1.5.
    let mut want = vec![("rapid", 1.5, 1.0), ("rapid", 2.1, 0.1)];
    for c in [0.05, 0.1] {
        want.extend([
            ("rapid", 2.1, -c),
            ("thread", 0.5, -c),
            ("rapid", 0.5, 0.1),
            ("rapid", 2.1, 0.1),
        ]);
    }
    assert_path(&path(&r), &want);
}

#[test]
fn face_thread_multi_letter_names() {
    // Face1 = M1, ZEnd = Z (final depth), depth = J, XStart = I, XEnd = X,
    // pitch = F, dStart = D, XClr = U, ZClr = W, angSt = Q- (start angle).
    let single = run_on(
        "hurco-lathe",
        &format!("{HEAD}G0 X3 Z1\nG78 M1 Z-.1 J.1 I2 X.5 F.1 D.05 U.2 W.3 Q-90\nM30\n"),
    );
    let long = run_on(
        "hurco-lathe",
        &format!(
            "{HEAD}G0 X3 Z1\nG78 Face1 ZEnd-.1 depth.1 XStart2 XEnd.5 pitch.1 dStart.05 \
             XClr.2 ZClr.3 angSt90\nM30\n"
        ),
    );
    ok(&single);
    ok(&long);
    assert_eq!(path(&single), path(&long));
    assert_eq!(single.events, long.events);
    // U .2 is the X clearance before the start (2.2), W .3 the Z
    // clearance (Z .3): the start point.
    assert_eq!(path(&single)[1], ("rapid", 2.2, 0.3));
}

#[test]
fn g78_alarms() {
    // (block, alarm, the text the alarm points at).
    let cases: &[(&str, &str, &str)] = &[
        // X+J of another sign than X: the X axis would cross the centre
        // (at J).
        ("G78 X.1 J-.2 K2 Z1 F.1 D.05", "HU-060", "J-.2"),
        // More than one of Z/H/T: at the second.
        ("G78 X1 J.1 K2 Z1 T1 F.1 D.05", "HU-060", "T1"),
        // Missing D, thread end, K: at G78.
        ("G78 X1 J.1 K2 Z1 F.1", "HU-015", "G78"),
        ("G78 X1 J.1 K2 F.1 D.05", "HU-015", "G78"),
        ("G78 X1 J.1 Z1 F.1 D.05", "HU-015", "G78"),
        // E with V1.
        ("G78 X1 J.1 K2 Z1 F.1 D.05 E.02 V1", "HU-060", "E.02"),
        // Finish passes deeper than J.
        ("G78 X1 J.1 K2 Z1 F.1 D.05 L.05 P3", "HU-060", "G78"),
        // B beyond 45°.
        ("G78 X1 J.1 K2 Z1 F.1 D.05 B50", "HU-014", "B50"),
        // X beyond Table 2 (845 in).
        ("G78 X900 J.1 K2 Z1 F.1 D.05", "HU-014", "X900"),
        // A face thread from X2 to X-.5 crosses the centre line (at X).
        ("G78 M1 Z-.1 J.1 I2 X-.5 F.1 D.05", "HU-060", "X-.5"),
        // Absurdly many passes: alarm before anything is allocated.
        ("G78 X1 J1 K2 Z1 F.1 D.0000001", "HU-014", "D.0000001"),
        ("G78 X1 J.1 K2 Z1 F.1 D.0001 Q360", "HU-014", "D.0001"),
        // U outside G78.
        ("G01 X1 U2 F.1", "HU-001", "U2"),
        // A G78 name outside G78.
        ("G01 X1 depth2 F.1", "HU-001", "depth2"),
    ];
    for (blk, code, at) in cases {
        let col = blk.find(at).unwrap() as u32 + 1;
        let r = run_on("hurco-lathe", &format!("{HEAD}G0 X3 Z3\n{blk}\nM30\n"));
        assert_eq!(alarm(&r), (*code, 3, col), "{blk}: {:?}", r.alarm);
    }
    // G96 in force: G78 needs G97.
    let r = run_on(
        "hurco-lathe",
        "G70 G90 G96 M03 S300\nG0 X3 Z3\nG78 X1 J.1 K2 Z1 F.1 D.05\nM30\n",
    );
    assert_eq!(alarm(&r), ("HU-060", 3, 1));
    // Spindle stopped.
    let r = run_on(
        "hurco-lathe",
        "G70 G90\nG0 X3 Z3\nG78 X1 J.1 K2 Z1 F.1 D.05\nM30\n",
    );
    assert_eq!(alarm(&r), ("HU-060", 3, 1));
}
