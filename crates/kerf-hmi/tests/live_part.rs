//! The simulated part following the cut (`--stock`): the part shown is the
//! trace's whole-program result until a run starts, then the part as the
//! axes cut it, and at the program's end the same part the trace made.

use std::sync::Arc;
use std::time::{Duration, Instant};

use kerf_hmi::command::Command;
use kerf_hmi::state::{Execution, Mode, State};
use kerf_hmi::Shared;

// A slot 30 mm long, 2 mm deep, with the 10 mm fallback end mill
// (kerf-sim's FALLBACK_RADIUS 5 mm: no D offset) in a 40 x 20 x 10 block.
const SLOT: &str =
    "G90 G17 G21 G54\nG00 X5. Y10. Z5.\nM03 S1000\nG01 Z-2. F600.\nX35.\nG00 Z5.\nM30\n";

fn server() -> Arc<Shared> {
    let profile = kerf_interp::Profile::builtin("hx-mc").unwrap();
    let make: kerf_hmi::server::MakeControl = Box::new(|| {
        let rt = kerf_control::runtime::Runtime::for_machine("hx-mc")?;
        Ok(Box::new(kerf_hmi::RuntimeControl::new(rt)) as Box<dyn kerf_hmi::Control>)
    });
    let s = Shared::new(make, profile, vec![], None, 2.0).unwrap();
    s.set_stock(Some(kerf_sim::Stock::parse("box:0,0,-10,40,20,0").unwrap()))
        .unwrap();
    s
}

fn state(s: &Shared) -> State {
    s.frames.borrow().state.clone()
}

fn wait<T>(what: &str, secs: u64, mut f: impl FnMut() -> Option<T>) -> T {
    let t0 = Instant::now();
    loop {
        if let Some(v) = f() {
            return v;
        }
        assert!(
            t0.elapsed() < Duration::from_secs(secs),
            "timed out waiting for {what}"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn volume(stl: &[u8]) -> f64 {
    let c = kerf_sim::stl::check(stl).expect("a binary STL");
    assert_eq!(c.bad_edges, 0, "not closed");
    c.volume
}

#[test]
fn the_part_follows_the_cut_and_ends_as_the_trace_made_it() {
    let s = server();
    s.load("slot.nc", SLOT).unwrap();
    s.with(|c| c.command(&Command::Mode(Mode::MEM)).unwrap())
        .unwrap();
    // Before the run: the trace's whole-program part.
    let whole = wait("the trace's part", 60, || {
        s.path.lock().unwrap().part.clone()
    });
    let v_whole = volume(&whole);
    // The slot: a 30 x 10 x 2 mm box and two half discs of radius 5,
    // 2 mm deep (600 + 157.08 mm³), in the 8000 mm³ block; on a grid of
    // cells (the view's 40 / 300 mm), so within a few cells' volume.
    let cut = 8000.0 - v_whole;
    assert!((cut - 757.08).abs() < 30.0, "cut {cut} mm³");
    assert!(s.path.lock().unwrap().live.is_none());

    s.with(|c| c.command(&Command::CycleStart).unwrap())
        .unwrap();
    // On the 30 mm feed (3 s at F600 at rate 2, after some 3 s of rapid from the
    // reference point before it): the first part written with material
    // gone has the plunge (a disc of radius 5, 2 mm deep) and not yet the
    // slot: the part shown follows the blocks the axes finished.
    let mid = wait("a part with the plunge", 60, || {
        let p = s.path.lock().unwrap();
        let live = p.live.clone()?;
        (volume(&live) < 7990.0).then_some(live)
    });
    let st = state(&s);
    assert_eq!(
        st.program.line, 5,
        "the feed ended before its part was checked"
    );
    let v_mid = volume(&mid);
    let plunge = 8000.0 - v_mid;
    assert!((plunge - 157.08).abs() < 15.0, "plunge {plunge} mm³");

    // At the end: the part cut is the one the trace made, byte for byte.
    wait("the program's end", 60, || {
        (state(&s).execution == Execution::PROGRAM_COMPLETED).then_some(())
    });
    let last = wait("the last part written", 10, || {
        let p = s.path.lock().unwrap();
        let live = p.live.clone()?;
        (volume(&live) < v_mid).then_some(live)
    });
    assert_eq!(volume(&last), v_whole);
    assert!(last == whole, "the cut part differs from the trace's");
    assert_eq!(s.path.lock().unwrap().shown_part().unwrap(), last);

    // A new program drops the part cut: the new trace's part is shown.
    let seq = state(&s).path.part_seq;
    s.load("none.nc", "G90 G00 X5. Y5. Z50.\nM30\n").unwrap();
    assert!(s.path.lock().unwrap().live.is_none());
    let fresh = wait("the new trace's part", 60, || {
        s.path.lock().unwrap().part.clone()
    });
    assert!((volume(&fresh) - 8000.0).abs() < 1e-6);
    s.publish();
    assert_ne!(state(&s).path.part_seq, seq);
}
