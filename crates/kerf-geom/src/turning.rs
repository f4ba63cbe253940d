//! Pure geometry of the lathe cycles (fanuc-semantics §1, §2 and its
//! Appendix A): the single cycles G90/G92/G94, the roughing passes of
//! G71/G72 (type I), the pattern copies of G73, the peck grid of G74/G75
//! and the thread passes of G76. Everything here works on points (x as a
//! radius, z) in program coordinates and returns a list of [`Mv`]; the
//! interpreter (interp/lathe.rs, interp/lathe_mrc.rs) turns them into
//! canonical moves. No state, no alarms with positions: errors are
//! [`CycleError`] values the caller positions.

/// A point of the ZX plane: `x` a radius, `z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct P {
    /// X as a radius.
    pub x: f64,
    /// Z.
    pub z: f64,
}

/// Shorthand for a point.
pub const fn p(x: f64, z: f64) -> P {
    P { x, z }
}

impl P {
    /// The point with X and Z exchanged (G72 and G75 are G71 and G74 with
    /// the axes swapped).
    pub fn swap(self) -> P {
        p(self.z, self.x)
    }
    fn add(self, o: P) -> P {
        p(self.x + o.x, self.z + o.z)
    }
    /// (z, x): the (first, second) axes of the ZX plane for arc geometry.
    pub fn zx(self) -> (f64, f64) {
        (self.z, self.x)
    }
}

/// One generated move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mv {
    /// Rapid traverse to the point.
    Rapid(P),
    /// Cutting feed to the point.
    Feed(P),
    /// Circular cut to `to` about `c` (G03 when `ccw`, seen in the ZX
    /// plane as G18 defines it).
    Arc {
        /// End point.
        to: P,
        /// Centre.
        c: P,
        /// Counter-clockwise (G03).
        ccw: bool,
    },
    /// Spindle-synchronised thread cut to the point.
    Thread(P),
}

impl Mv {
    /// The end point.
    pub fn to(&self) -> P {
        match *self {
            Mv::Rapid(t) | Mv::Feed(t) | Mv::Thread(t) | Mv::Arc { to: t, .. } => t,
        }
    }
    /// The move with X and Z exchanged (an arc changes direction: the swap
    /// is a reflection).
    pub fn swap(self) -> Mv {
        match self {
            Mv::Rapid(t) => Mv::Rapid(t.swap()),
            Mv::Feed(t) => Mv::Feed(t.swap()),
            Mv::Thread(t) => Mv::Thread(t.swap()),
            Mv::Arc { to, c, ccw } => Mv::Arc {
                to: to.swap(),
                c: c.swap(),
                ccw: !ccw,
            },
        }
    }
}

/// A segment of a finishing shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    /// Start point.
    pub from: P,
    /// End point.
    pub to: P,
    /// `None` for a line, else the arc's centre and direction.
    pub arc: Option<(P, bool)>,
}

impl Seg {
    fn shifted(&self, d: P) -> Seg {
        Seg {
            from: self.from.add(d),
            to: self.to.add(d),
            arc: self.arc.map(|(c, ccw)| (c.add(d), ccw)),
        }
    }
    fn swap(&self) -> Seg {
        Seg {
            from: self.from.swap(),
            to: self.to.swap(),
            arc: self.arc.map(|(c, ccw)| (c.swap(), !ccw)),
        }
    }
    /// The move that follows this segment.
    pub fn mv(&self) -> Mv {
        match self.arc {
            None => Mv::Feed(self.to),
            Some((c, ccw)) => Mv::Arc {
                to: self.to,
                c,
                ccw,
            },
        }
    }
    /// The extremes (min x, min z, max x, max z) of the segment.
    fn bounds(&self) -> (f64, f64, f64, f64) {
        match self.arc {
            None => (
                self.from.x.min(self.to.x),
                self.from.z.min(self.to.z),
                self.from.x.max(self.to.x),
                self.from.z.max(self.to.z),
            ),
            Some((c, ccw)) => {
                // bbox in (z, x) order.
                let (z0, x0, z1, x1) = crate::arc::bbox(self.from.zx(), self.to.zx(), c.zx(), ccw);
                (x0, z0, x1, z1)
            }
        }
    }
}

/// Why a cycle cannot be made; the caller turns it into a positioned alarm.
#[derive(Clone, Debug, PartialEq)]
pub enum CycleError {
    /// A value out of its range (Fanuc PS062): the message says which.
    Value(String),
    /// The shape is not monotonic (Fanuc PS064): the index of the first
    /// offending segment, and the axis name.
    NotMonotonic(usize, char),
    /// More moves than the bound for one cycle block.
    TooManyMoves,
}

/// Most moves one cycle block may generate (the G71 levels, G74 pecks or
/// G76 passes of a bad depth): beyond, [`CycleError::TooManyMoves`].
pub const MAX_MOVES: usize = 200_000;

const EPS: f64 = 1e-9;

fn sign(v: f64) -> f64 {
    if v > EPS {
        1.0
    } else if v < -EPS {
        -1.0
    } else {
        0.0
    }
}

fn push(out: &mut Vec<Mv>, m: Mv) -> Result<(), CycleError> {
    if out.len() >= MAX_MOVES {
        return Err(CycleError::TooManyMoves);
    }
    out.push(m);
    Ok(())
}

// ---- single cycles -----------------------------------------------------------

/// G90 (fanuc-semantics §2.1, A.5): from `a`, rapid X to the cut start
/// (`e.x + r` at `a.z`), feed to `e`, feed X back to `a.x`, rapid to `a`.
/// `r` is the radius difference start − end of the taper.
pub fn g90(a: P, e: P, r: f64) -> [Mv; 4] {
    [
        Mv::Rapid(p(e.x + r, a.z)),
        Mv::Feed(e),
        Mv::Feed(p(a.x, e.z)),
        Mv::Rapid(a),
    ]
}

/// G94 (fanuc-semantics §2.3, A.5): rapid Z to the cut start (`e.z + r` at
/// `a.x`), feed to `e`, feed Z back to `a.z`, rapid to `a`.
pub fn g94(a: P, e: P, r: f64) -> [Mv; 4] {
    [
        Mv::Rapid(p(a.x, e.z + r)),
        Mv::Feed(e),
        Mv::Feed(p(e.x, a.z)),
        Mv::Rapid(a),
    ]
}

/// G92 (fanuc-semantics §2.2): as G90 with a thread cut and rapids; with a
/// thread chamfer `c` > 0 (M76) the thread ends with a 45° pull-out of
/// length `c` in Z toward the start side in X, still synchronised.
pub fn g92(a: P, e: P, r: f64, c: f64) -> Result<Vec<Mv>, CycleError> {
    let s = p(e.x + r, a.z);
    let mut v = vec![Mv::Rapid(s)];
    let dirx = sign(a.x - e.x);
    if c > EPS && dirx != 0.0 {
        let len = (e.z - s.z).abs();
        if c > len + EPS {
            return Err(CycleError::Value(format!(
                "thread chamfer {c:.4} longer than the thread {len:.4}"
            )));
        }
        let zc = e.z - sign(e.z - s.z) * c;
        let xc = s.x
            + (e.x - s.x)
                * if len > EPS {
                    (zc - s.z) / (e.z - s.z)
                } else {
                    1.0
                };
        v.push(Mv::Thread(p(xc, zc)));
        v.push(Mv::Thread(p(xc + dirx * c, e.z)));
    } else {
        v.push(Mv::Thread(e));
    }
    v.push(Mv::Rapid(p(a.x, e.z)));
    v.push(Mv::Rapid(a));
    Ok(v)
}

// ---- G71 / G72 ---------------------------------------------------------------

/// The first-block and second-block data of G71/G72 (radius values).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rough {
    /// Δd: depth of cut per pass (> 0).
    pub depth: f64,
    /// e: escape at 45° after each cut (≥ 0).
    pub escape: f64,
    /// Finishing allowance in X (radius, signed: Δu/2).
    pub allow_x: f64,
    /// Finishing allowance in Z (signed: Δw).
    pub allow_z: f64,
}

const NO_LENGTH_Z: &str = "the shape has no length in Z";
const NO_LENGTH_X: &str = "the shape has no length in X";

/// The direction of the cutting along Z: that of the shape's first
/// segment that moves in Z (0 if none does). A shape that later comes back
/// to (or past) its start Z is then not monotonic at the segment that turns
/// back, which is the one the alarm names.
fn cutting_direction(segs: &[Seg]) -> f64 {
    segs.iter()
        .map(|s| sign(s.to.z - s.from.z))
        .find(|&d| d != 0.0)
        .unwrap_or(0.0)
}

/// What G71 types I and II check and prepare alike: Δd > 0 and e ≥ 0, the
/// shape shifted by the allowances, its first point, the infeed sign in X
/// (from the start point toward the shape) and the cutting direction in Z.
fn rough_setup(
    a: P,
    start: P,
    shape: &[Seg],
    r: &Rough,
) -> Result<(P, Vec<Seg>, f64, f64), CycleError> {
    if r.depth <= 0.0 {
        return Err(CycleError::Value(format!(
            "depth of cut Δd = {} must be positive",
            r.depth
        )));
    }
    if r.escape < 0.0 {
        return Err(CycleError::Value("escape e must not be negative".into()));
    }
    let shift = p(r.allow_x, r.allow_z);
    let first = start.add(shift);
    let segs: Vec<Seg> = shape.iter().map(|s| s.shifted(shift)).collect();
    let sx = sign(first.x - a.x);
    let sz = cutting_direction(&segs);
    if sx == 0.0 {
        return Err(CycleError::Value(
            "the start point is level with the shape's first point in X: nothing to rough".into(),
        ));
    }
    if sz == 0.0 {
        return Err(CycleError::Value(NO_LENGTH_Z.into()));
    }
    Ok((first, segs, sx, sz))
}

/// Segment `i` goes the cutting direction `sz` in Z (flat allowed) and an
/// arc stays within its end points' Z range.
fn check_monotonic_z(i: usize, s: &Seg, sz: f64) -> Result<(), CycleError> {
    let (_, z0, _, z1) = s.bounds();
    let (zlo, zhi) = (s.from.z.min(s.to.z), s.from.z.max(s.to.z));
    if sz * (s.to.z - s.from.z) < -1e-6 || z0 < zlo - 1e-6 || z1 > zhi + 1e-6 {
        return Err(CycleError::NotMonotonic(i, 'Z'));
    }
    Ok(())
}

/// G71 type I (fanuc-semantics §1.2, A.1): the roughing levels in X from
/// the start point `a`, each cut parallel to Z until the shape shifted by
/// the allowances, the 45° escape and the return in Z, then the
/// semi-finish pass along the shifted shape and the rapid back to `a`.
/// `start` is A′ (the end of block ns), `shape` the segments A′ → B.
/// `ns_rapid`: block ns is G00 (infeeds rapid) rather than G01.
pub fn g71(
    a: P,
    start: P,
    shape: &[Seg],
    r: Rough,
    ns_rapid: bool,
    out: &mut Vec<Mv>,
) -> Result<(), CycleError> {
    let (first, segs, sx, sz) = rough_setup(a, start, shape, &r)?;
    // Type I: monotonic in both axes (flat allowed); X goes back toward
    // the start point's side.
    for (i, s) in segs.iter().enumerate() {
        check_monotonic_z(i, s, sz)?;
        let (x0, _, x1, _) = s.bounds();
        let (xlo, xhi) = (s.from.x.min(s.to.x), s.from.x.max(s.to.x));
        if sx * (s.to.x - s.from.x) > 1e-6 || x0 < xlo - 1e-6 || x1 > xhi + 1e-6 {
            return Err(CycleError::NotMonotonic(i, 'X'));
        }
    }
    let infeed = |t: P| if ns_rapid { Mv::Rapid(t) } else { Mv::Feed(t) };
    let levels = ((first.x - a.x).abs() / r.depth).ceil();
    if levels * 4.0 + segs.len() as f64 > MAX_MOVES as f64 {
        return Err(CycleError::TooManyMoves);
    }
    let mut k = 1.0;
    loop {
        let mut level = a.x + sx * k * r.depth;
        let is_last = sx * (level - first.x) >= -EPS;
        if is_last {
            level = first.x;
        }
        push(out, infeed(p(level, a.z)))?;
        let zh = cut_end(level, sx, first, &segs);
        push(out, Mv::Feed(p(level, zh)))?;
        push(out, Mv::Rapid(p(level - sx * r.escape, zh - sz * r.escape)))?;
        push(out, Mv::Rapid(p(level - sx * r.escape, a.z)))?;
        if is_last {
            break;
        }
        k += 1.0;
    }
    push(out, infeed(first))?;
    for s in &segs {
        push(out, s.mv())?;
    }
    push(out, Mv::Rapid(a))
}

/// Where the cut at X = `level` ends: the first point, going along the
/// shape from its start, where the shape comes out of the material side
/// of the level (strictly shallower than it); the shape's end if never.
fn cut_end(level: f64, sx: f64, first: P, segs: &[Seg]) -> f64 {
    let shallow = |x: f64| sx * (x - level) < -1e-7;
    if shallow(first.x) {
        return first.z;
    }
    for s in segs {
        if shallow(s.from.x) {
            return s.from.z;
        }
        if !shallow(s.to.x) {
            continue;
        }
        match s.arc {
            None => {
                let t = (level - s.from.x) / (s.to.x - s.from.x);
                return s.from.z + t * (s.to.z - s.from.z);
            }
            Some((c, _)) => {
                let rad = (s.from.x - c.x).hypot(s.from.z - c.z);
                let dx = level - c.x;
                let h = (rad * rad - dx * dx).max(0.0).sqrt();
                let (zlo, zhi) = (s.from.z.min(s.to.z), s.from.z.max(s.to.z));
                // The arc is monotonic (checked): one root lies on it.
                let cand = [c.z - h, c.z + h];
                let best = cand
                    .iter()
                    .copied()
                    .min_by(|a, b| {
                        let da = (a.clamp(zlo, zhi) - a).abs();
                        let db = (b.clamp(zlo, zhi) - b).abs();
                        da.total_cmp(&db)
                    })
                    .unwrap_or(s.to.z);
                return best.clamp(zlo, zhi);
            }
        }
    }
    segs.last().map(|s| s.to.z).unwrap_or(first.z)
}

/// The Z intervals (in cutting order) where the shape lies at or beyond
/// X = `level` in the infeed direction `sx` — where a cut at that level
/// is in material. The flag: the first interval begins at the shape's
/// start (it is connected to the start side).
pub fn level_intervals(level: f64, sx: f64, first: P, segs: &[Seg]) -> (Vec<(f64, f64)>, bool) {
    let inside = |x: f64| sx * (x - level) >= -1e-7;
    let mut out = Vec::new();
    let mut open = inside(first.x).then_some(first.z);
    let connected = open.is_some();
    let mut toggle = |z: f64, open: &mut Option<f64>| match open.take() {
        Some(z0) => out.push((z0, z)),
        None => *open = Some(z),
    };
    for s in segs {
        match s.arc {
            None => {
                // Sub-ranges split where x = level.
                let mut cuts = vec![0.0];
                let dx = s.to.x - s.from.x;
                if dx.abs() > 1e-12 {
                    let t = (level - s.from.x) / dx;
                    if t > 1e-12 && t < 1.0 - 1e-12 {
                        cuts.push(t);
                    }
                }
                cuts.push(1.0);
                for w in cuts.windows(2) {
                    let xm = s.from.x + dx * (w[0] + w[1]) / 2.0;
                    if inside(xm) != open.is_some() {
                        toggle(s.from.z + (s.to.z - s.from.z) * w[0], &mut open);
                    }
                }
            }
            Some((c, ccw)) => {
                let r = (s.from.x - c.x).hypot(s.from.z - c.z);
                let sweep = crate::arc::sweep(s.from.zx(), s.to.zx(), c.zx(), ccw);
                let a0 = (s.from.x - c.x).atan2(s.from.z - c.z);
                let at = |d: f64| {
                    let a = if ccw { a0 + d } else { a0 - d };
                    p(c.x + r * a.sin(), c.z + r * a.cos())
                };
                let mut cuts = vec![0.0];
                let sn = (level - c.x) / r;
                if sn.abs() <= 1.0 {
                    let b = sn.asin();
                    let mut ds: Vec<f64> = [b, std::f64::consts::PI - b]
                        .iter()
                        .map(|&phi| {
                            let d = if ccw { phi - a0 } else { a0 - phi };
                            d.rem_euclid(std::f64::consts::TAU)
                        })
                        .filter(|&d| d > 1e-12 && d < sweep - 1e-12)
                        .collect();
                    ds.sort_by(f64::total_cmp);
                    cuts.extend(ds);
                }
                cuts.push(sweep);
                for w in cuts.windows(2) {
                    let m = at((w[0] + w[1]) / 2.0);
                    if inside(m.x) != open.is_some() {
                        let q = if w[0] == 0.0 { s.from } else { at(w[0]) };
                        toggle(q.z, &mut open);
                    }
                }
            }
        }
    }
    if let Some(z0) = open {
        let end = segs.last().map(|s| s.to.z).unwrap_or(first.z);
        out.push((z0, end));
    }
    // A level that only touches the shape (the bottom of an arc) cuts
    // nothing there.
    let mut k = 0;
    out.retain(|iv| {
        k += 1;
        (k == 1 && connected) || (iv.1 - iv.0).abs() > 1e-9
    });
    (out, connected)
}

/// G71 type II (fanuc-semantics §1.2 "Type II", marked uncertain there;
/// kerf's reading is in docs/dialects.md): the shape may go back in X
/// (pockets), Z stays monotonic. First the region connected to the start
/// side, level by level exactly as type I (levels down to the shape's
/// start); then each pocket in turn in the cutting direction, roughed
/// level by level from the level where it separates: the tool travels
/// at the escape height of the level above the pocket, feeds down at the
/// pocket's entry wall, cuts to its exit wall and escapes at 45°; a
/// pocket that splits at a deeper level is finished branch by branch.
/// Then a rapid to X of the start point, to the start point's Z, and the
/// semi-finish pass as in type I.
pub fn g71_type2(
    a: P,
    start: P,
    shape: &[Seg],
    r: Rough,
    ns_rapid: bool,
    out: &mut Vec<Mv>,
) -> Result<(), CycleError> {
    let (first, segs, sx, sz) = rough_setup(a, start, shape, &r)?;
    // Z monotonic (flat allowed); X free.
    for (i, s) in segs.iter().enumerate() {
        check_monotonic_z(i, s, sz)?;
    }
    // The deepest point of the shape in the infeed direction.
    let mut deep = first.x;
    for s in &segs {
        let (x0, _, x1, _) = s.bounds();
        for x in [x0, x1] {
            if sx * (x - deep) > 0.0 {
                deep = x;
            }
        }
    }
    let n = ((deep - a.x).abs() / r.depth).ceil();
    if n * 4.0 > MAX_MOVES as f64 {
        return Err(CycleError::TooManyMoves);
    }
    // General levels down to the deepest point.
    let mut levels = Vec::new();
    let mut k = 1.0;
    loop {
        let l = a.x + sx * k * r.depth;
        if sx * (l - deep) >= -EPS {
            levels.push(deep);
            break;
        }
        levels.push(l);
        k += 1.0;
    }
    let ivs: Vec<(Vec<(f64, f64)>, bool)> = levels
        .iter()
        .map(|&l| level_intervals(l, sx, first, &segs))
        .collect();
    let infeed = |t: P| if ns_rapid { Mv::Rapid(t) } else { Mv::Feed(t) };
    // 1. The region connected to the start side: type I levels.
    let mut k = 1.0;
    loop {
        let mut level = a.x + sx * k * r.depth;
        let is_last = sx * (level - first.x) >= -EPS;
        if is_last {
            level = first.x;
        }
        let (iv, conn) = level_intervals(level, sx, first, &segs);
        let zh = if conn { iv[0].1 } else { first.z };
        push(out, infeed(p(level, a.z)))?;
        push(out, Mv::Feed(p(level, zh)))?;
        push(out, Mv::Rapid(p(level - sx * r.escape, zh - sz * r.escape)))?;
        push(out, Mv::Rapid(p(level - sx * r.escape, a.z)))?;
        if is_last {
            break;
        }
        k += 1.0;
    }
    g71_pockets(a, (sx, sz), r.escape, &levels, &ivs, out)?;
    push(out, infeed(first))?;
    for s in &segs {
        push(out, s.mv())?;
    }
    push(out, Mv::Rapid(a))
}

/// G71 type II, the pockets (fanuc-semantics §1.2): the intervals of each
/// level (`ivs`, per entry of `levels`) not connected to the start side
/// whose parent, one level up, is; each is entered at its parent level's
/// escape height and cut depth first, then the tool returns to `a`.
/// `signs`: the infeed (X) and cutting (Z) directions.
fn g71_pockets(
    a: P,
    signs: (f64, f64),
    escape: f64,
    levels: &[f64],
    ivs: &[(Vec<(f64, f64)>, bool)],
    out: &mut Vec<Mv>,
) -> Result<(), CycleError> {
    let (sx, sz) = signs;
    // 2. Pockets: intervals not connected to the start side whose parent
    // (the interval one level up that holds them) is connected.
    let within = |inner: (f64, f64), outer: (f64, f64)| {
        let (lo, hi) = (outer.0.min(outer.1) - 1e-7, outer.0.max(outer.1) + 1e-7);
        inner.0 >= lo && inner.0 <= hi && inner.1 >= lo && inner.1 <= hi
    };
    let mut roots: Vec<(usize, (f64, f64))> = Vec::new();
    for (i, (iv, conn)) in ivs.iter().enumerate() {
        for (j, &int) in iv.iter().enumerate() {
            if j == 0 && *conn {
                continue;
            }
            let parent_connected = if i == 0 {
                true
            } else {
                let (piv, pconn) = &ivs[i - 1];
                *pconn && within(int, piv[0])
            };
            if parent_connected {
                roots.push((i, int));
            }
        }
    }
    roots.sort_by(|x, y| (sz * x.1 .0).total_cmp(&(sz * y.1 .0)));
    let level_of = |i: usize| if i == 0 { a.x } else { levels[i - 1] };
    let mut travel: Option<f64> = None;
    for root in &roots {
        let lp = level_of(root.0) - sx * escape;
        // Travel at the shallower of this and the last pocket's heights.
        let h = match travel {
            Some(t) if sx * (t - lp) < 0.0 => t,
            _ => lp,
        };
        let cur = out.last().map(|m| m.to()).unwrap_or(a);
        push(out, Mv::Rapid(p(h, cur.z)))?;
        push(out, Mv::Rapid(p(h, root.1 .0)))?;
        travel = Some(lp);
        // Depth first through the pocket.
        let mut stack = vec![(root.0, root.1, true)];
        while let Some((i, (z0, z1), first_child)) = stack.pop() {
            let l = levels[i];
            if !first_child {
                let cur = out.last().map(|m| m.to()).unwrap_or(a);
                let hp = level_of(i) - sx * escape;
                push(out, Mv::Rapid(p(hp, cur.z)))?;
                push(out, Mv::Rapid(p(hp, z0)))?;
            }
            push(out, Mv::Feed(p(l, z0)))?;
            push(out, Mv::Feed(p(l, z1)))?;
            push(out, Mv::Rapid(p(l - sx * escape, z1 - sz * escape)))?;
            if i + 1 < levels.len() {
                let kids: Vec<(f64, f64)> = ivs[i + 1]
                    .0
                    .iter()
                    .copied()
                    .filter(|&c| within(c, (z0, z1)))
                    .collect();
                for c in kids.into_iter().rev() {
                    stack.push((i + 1, c, false));
                }
            }
        }
    }
    if !roots.is_empty() {
        let cur = out.last().map(|m| m.to()).unwrap_or(a);
        push(out, Mv::Rapid(p(a.x, cur.z)))?;
        push(out, Mv::Rapid(p(a.x, a.z)))?;
    }
    Ok(())
}

/// G72: G71 with X and Z exchanged (levels in Z by Δd, cuts parallel to
/// X, return in X); `r.depth` is the Z depth per pass, `type2` selects
/// [`g71_type2`] (pockets in Z).
pub fn g72(
    a: P,
    start: P,
    shape: &[Seg],
    r: Rough,
    ns_rapid: bool,
    type2: bool,
    out: &mut Vec<Mv>,
) -> Result<(), CycleError> {
    let sw: Vec<Seg> = shape.iter().map(Seg::swap).collect();
    let rs = Rough {
        allow_x: r.allow_z,
        allow_z: r.allow_x,
        ..r
    };
    let n0 = out.len();
    let res = if type2 {
        g71_type2(a.swap(), start.swap(), &sw, rs, ns_rapid, out)
    } else {
        g71(a.swap(), start.swap(), &sw, rs, ns_rapid, out)
    };
    for m in &mut out[n0..] {
        *m = m.swap();
    }
    res.map_err(|e| match e {
        CycleError::NotMonotonic(i, ax) => {
            CycleError::NotMonotonic(i, if ax == 'X' { 'Z' } else { 'X' })
        }
        CycleError::Value(m) if m == NO_LENGTH_Z => CycleError::Value(NO_LENGTH_X.into()),
        e => e,
    })
}

// ---- G73 ---------------------------------------------------------------------

/// G73 (fanuc-semantics §1.4, A.2): `divisions` copies of the shape, copy
/// n shifted by relief·(d−n)/(d−1) plus the allowance; each approached in
/// the mode of block ns from the current point, followed at the cutting
/// feed, then a rapid back to `a`. `relief` = (Δi, Δk), `allow` =
/// (Δu/2, Δw).
#[allow(clippy::too_many_arguments)] // the cycle's own data, named as in the manual
pub fn g73(
    a: P,
    start: P,
    shape: &[Seg],
    relief: P,
    allow: P,
    divisions: u32,
    ns_rapid: bool,
    out: &mut Vec<Mv>,
) -> Result<(), CycleError> {
    if divisions == 0 {
        return Err(CycleError::Value(
            "number of divisions d must be at least 1".into(),
        ));
    }
    if (divisions as usize).saturating_mul(shape.len() + 2) > MAX_MOVES {
        return Err(CycleError::TooManyMoves);
    }
    for n in 1..=divisions {
        let f = if divisions > 1 {
            (divisions - n) as f64 / (divisions - 1) as f64
        } else {
            0.0
        };
        let off = p(relief.x * f + allow.x, relief.z * f + allow.z);
        let s0 = start.add(off);
        push(
            out,
            if ns_rapid {
                Mv::Rapid(s0)
            } else {
                Mv::Feed(s0)
            },
        )?;
        for s in shape {
            push(out, s.shifted(off).mv())?;
        }
        push(out, Mv::Rapid(a))?;
    }
    Ok(())
}

// ---- G74 / G75 ---------------------------------------------------------------

/// The data of a G74 peck block (radius values): `end` = (X of the last
/// column, Z of the bottom); `shift` Δi between columns, `peck` Δk per
/// peck, `relief` Δd at the bottom, `escape` e after each peck; `columns`
/// is false when X(U) and P were omitted (one column on the spot).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peck {
    /// End point (last column X, bottom Z).
    pub end: P,
    /// Δi: shift between columns (> 0 when there are several).
    pub shift: f64,
    /// Δk: depth of each peck (> 0).
    pub peck: f64,
    /// Δd: relief at the bottom.
    pub relief: f64,
    /// e: retract after each peck.
    pub escape: f64,
    /// X(U) and P given.
    pub columns: bool,
}

/// G74 (fanuc-semantics §1.6, A.3): columns of pecks in Z; after each
/// column a relief of Δd in X back toward the start side (the sign of Δd
/// picks the side when there is one column), a rapid back to Z of the start
/// and a rapid to the next column; finally a rapid to `a`.
pub fn g74(a: P, k: Peck, out: &mut Vec<Mv>) -> Result<(), CycleError> {
    let dirx = sign(k.end.x - a.x);
    let dirz = sign(k.end.z - a.z);
    if dirz != 0.0 && k.peck <= 0.0 {
        return Err(CycleError::Value(
            "peck depth Δk (Q) must be positive".into(),
        ));
    }
    if dirx != 0.0 && k.shift <= 0.0 {
        return Err(CycleError::Value(
            "shift Δi (P) must be positive when the end X differs from the start".into(),
        ));
    }
    let cols = if dirx == 0.0 {
        1.0
    } else {
        ((k.end.x - a.x).abs() / k.shift).ceil() + 1.0
    };
    let pecks = if dirz == 0.0 {
        1.0
    } else {
        ((k.end.z - a.z).abs() / k.peck).ceil()
    };
    if cols * (pecks * 2.0 + 4.0) > MAX_MOVES as f64 {
        return Err(CycleError::TooManyMoves);
    }
    let mut x = a.x;
    loop {
        let mut z = a.z;
        loop {
            let mut zn = z + dirz * k.peck;
            if dirz * (zn - k.end.z) >= -EPS {
                zn = k.end.z;
            }
            push(out, Mv::Feed(p(x, zn)))?;
            if (zn - k.end.z).abs() <= EPS {
                break;
            }
            push(out, Mv::Rapid(p(x, zn - dirz * k.escape)))?;
            z = zn;
        }
        let mut xr = x;
        if k.relief != 0.0 {
            xr = if k.columns && dirx != 0.0 {
                x - dirx * k.relief.abs()
            } else {
                x + k.relief
            };
            push(out, Mv::Rapid(p(xr, k.end.z)))?;
        }
        push(out, Mv::Rapid(p(xr, a.z)))?;
        if dirx == 0.0 || (x - k.end.x).abs() <= EPS {
            break;
        }
        x += dirx * k.shift;
        if dirx * (x - k.end.x) >= -EPS {
            x = k.end.x;
        }
        push(out, Mv::Rapid(p(x, a.z)))?;
    }
    push(out, Mv::Rapid(a))
}

/// G75 (fanuc-semantics §1.7): G74 with X and Z exchanged; `k.shift` is
/// Δk (Q, the Z shift between grooves), `k.peck` is Δi (P, the X peck),
/// `k.relief` Δd in Z, `k.columns` false when Z(W) and Q were omitted.
pub fn g75(a: P, k: Peck, out: &mut Vec<Mv>) -> Result<(), CycleError> {
    let n0 = out.len();
    let ks = Peck {
        end: k.end.swap(),
        ..k
    };
    let r = g74(a.swap(), ks, out);
    for m in &mut out[n0..] {
        *m = m.swap();
    }
    r
}

// ---- G76 ---------------------------------------------------------------------

/// The data of G76 (radius values, mm): first block m, r, a, Δdmin, d;
/// second block end point, taper i, height k, first depth Δd, lead L.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Thread {
    /// m: number of finishing passes.
    pub finish_passes: u32,
    /// r: run-out chamfer in 0.1 L steps.
    pub chamfer: u32,
    /// a: tool angle in degrees.
    pub angle: f64,
    /// Δdmin: minimum depth increment.
    pub min_depth: f64,
    /// d: finishing allowance.
    pub allowance: f64,
    /// Thread end point at the root.
    pub end: P,
    /// i: radius difference start − end (taper).
    pub taper: f64,
    /// k: thread height.
    pub height: f64,
    /// Δd: depth of the first cut.
    pub first_depth: f64,
    /// L: lead.
    pub lead: f64,
}

/// The G76 pass depths from the crest (fanuc-semantics §1.8, A.4): Δd·√n
/// with the Δdmin floor, the last rough pass clamped to k − d, then m
/// finishing passes at k.
pub fn g76_depths(t: &Thread) -> Result<Vec<f64>, CycleError> {
    if t.height <= 0.0 {
        return Err(CycleError::Value(
            "thread height k (P) must be positive".into(),
        ));
    }
    if t.first_depth <= 0.0 {
        return Err(CycleError::Value(
            "first depth Δd (Q) must be positive".into(),
        ));
    }
    if t.allowance < 0.0 || t.allowance >= t.height {
        return Err(CycleError::Value(
            "finishing allowance d must be at least 0 and less than the height k".into(),
        ));
    }
    let rough_end = t.height - t.allowance;
    let mut v = Vec::new();
    let mut d = t.first_depth;
    let mut n = 1.0f64;
    while d < rough_end - EPS {
        if v.len() >= MAX_MOVES / 8 {
            return Err(CycleError::TooManyMoves);
        }
        v.push(d);
        n += 1.0;
        d = (t.first_depth * n.sqrt()).max(d + t.min_depth);
    }
    v.push(rough_end);
    for _ in 0..t.finish_passes {
        v.push(t.height);
    }
    Ok(v)
}

/// G76 passes (A.4): per depth D a rapid to the pass start (flank infeed:
/// Z shifted by (k − D)·tan(a/2) against the cutting direction), the
/// thread cut (with the 45° run-out of r·0.1·L when r > 0), a rapid to X
/// of the start and a rapid to `a`.
pub fn g76(a: P, t: &Thread, out: &mut Vec<Mv>) -> Result<(), CycleError> {
    if ![0.0, 29.0, 30.0, 55.0, 60.0, 80.0].contains(&t.angle) {
        return Err(CycleError::Value(format!(
            "tool angle a = {} is not 80, 60, 55, 30, 29 or 0",
            t.angle
        )));
    }
    if t.lead <= 0.0 {
        return Err(CycleError::Value("thread lead F missing or zero".into()));
    }
    let depths = g76_depths(t)?;
    let dirx = sign(a.x - t.end.x);
    let dirz = sign(t.end.z - a.z);
    if dirx == 0.0 || dirz == 0.0 {
        return Err(CycleError::Value(
            "the start point must differ from the thread end in X and in Z".into(),
        ));
    }
    let len = (t.end.z - a.z).abs();
    let c = t.chamfer as f64 * 0.1 * t.lead;
    if c > len + EPS {
        return Err(CycleError::Value(format!(
            "thread run-out {c:.4} longer than the thread {len:.4}"
        )));
    }
    // Root line from (end.x + i, a.z) to the end point.
    let root = |z: f64| t.end.x + t.taper * (t.end.z - z) / (t.end.z - a.z);
    let tan = (t.angle.to_radians() / 2.0).tan();
    for d in depths {
        let zs = a.z - dirz * (t.height - d) * tan;
        let at = |z: f64| root(z) + dirx * (t.height - d);
        push(out, Mv::Rapid(p(at(zs), zs)))?;
        if c > EPS {
            let zc = t.end.z - dirz * c;
            let xc = at(zc);
            push(out, Mv::Thread(p(xc, zc)))?;
            push(out, Mv::Thread(p(xc + dirx * c, t.end.z)))?;
        } else {
            push(out, Mv::Thread(p(at(t.end.z), t.end.z)))?;
        }
        let cz = out.last().map(|m| m.to().z).unwrap_or(t.end.z);
        push(out, Mv::Rapid(p(a.x, cz)))?;
        push(out, Mv::Rapid(a))?;
    }
    Ok(())
}
