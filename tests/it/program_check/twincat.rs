//! A Beckhoff TwinCAT CNC (TF5200, the ISG kernel's DIN 66025 dialect) program, read
//! strictly: each block tokenized against the channel's axis names, words the check does
//! not model refused, the tested axis simulated in machine coordinates through the zero
//! offsets, G53, #MCS, incremental moves and a modulo axis's direction signs.
//!
//! Rules and their sources (Beckhoff Information System, TF5200 programming manual):
//! - "Axis commands": an axis name of more than one character takes `=` before its value
//!   (`X1=10.000`); after a one-letter name the value follows directly. So `X110.000` is
//!   axis X at 110, refused here when X is not a channel axis.
//! - "Block-specific comments": `(…)` (nesting allowed; open to the block end) and `;` to
//!   the block end. "NC block structure": an optional `N` number first. "Structure of NC
//!   control data": `%` and the program's name first.
//! - "Dwell time (G04), (#TIME)": `G04 <first main axis><s>` or `#TIME <s>`, alone in the
//!   block (a # command excludes other words but the block number).
//! - "Zero offsets (G53/G54/...G59)": G53 deselects the zero offset (P-ZERO-00001 = 0,
//!   the default) and is the initial state unless P-ZERO-00002 names another; G54..G59
//!   select one; a new offset acts from the next absolute position. G92 (reference point
//!   offset) is refused: it changes offsets. "Temporary transition to the machine
//!   coordinate system (#MCS ON/OFF)": all offsets off (a licensed extension).
//!   "Suppressing offsets (#SUPPRESS OFFSETS)": the axis positions of that block without
//!   any offset (kinematic and CS offsets excepted), non-modal, G90 only (ID 20985).
//! - "Programming modulo axes" (default mode): in G90 the first sign after the axis name is
//!   the direction (`C-5` is 5° reached turning negative), no sign the shorter way, at most
//!   one turn (the value modulo 360); in G91 the value is the signed rotation, and a second
//!   sign is refused (error ID 20958). Long names cannot take the direction signs there:
//!   a signed value after `=` on a modulo axis is refused.
//! - Units, feed mode and motion: G71 (metric), G94 and G01/G00 must be set before a move
//!   (channel defaults are parameters); G70 and G95 are refused.

use super::machine::{Feed, Refusal, Trace, Tracker, number, refuse, turn};

/// The machine the program runs on.
#[derive(Debug, Clone)]
pub struct Isg {
    /// The channel's axis names (first the first main axis, for `G04 X…`); the tested one.
    pub channel: Vec<String>,
    pub axis: String,
    /// The tested axis's zero offsets: index 0 is the G53 data block (zero), 1..=6 G54..G59;
    /// the one active at the start (P-ZERO-00002).
    pub zero: [f64; 7],
    pub active: usize,
    /// A modulo axis (P-AXIS-00015).
    pub modulo: bool,
    pub initial: f64,
}

/// A word of a block.
#[derive(Debug, Clone, PartialEq)]
enum Word {
    /// An address letter and its number text: `G01`, `F1000`, `M30`, `X10`.
    Letter(char, String),
    /// An axis name (one or more characters) and its value text.
    Axis(String, String, bool),
    /// `#TIME 2.5`, `#MCS ON`.
    Hash(String),
}

fn words(n: usize, line: &str, code: &str, m: &Isg) -> Result<Vec<Word>, Refusal> {
    let code = code.trim();
    if let Some(h) = code.strip_prefix('#') {
        return Ok(vec![Word::Hash(h.trim().to_string())]);
    }
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if c[i].is_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        while i < c.len() && (c[i].is_ascii_alphanumeric() || c[i] == '_') {
            i += 1;
        }
        let ident: String = c[start..i].iter().collect();
        let mut j = i;
        while j < c.len() && c[j] == ' ' {
            j += 1;
        }
        if j < c.len() && c[j] == '=' && ident.len() > 1 {
            let value = take_value(&c, j + 1);
            i = j + 1 + value.chars().count();
            out.push(Word::Axis(ident, value.trim().to_string(), true));
            continue;
        }
        let letter = c[start];
        if !letter.is_ascii_uppercase() {
            return refuse(n, line, format!("`{letter}` where a word begins"));
        }
        let value = take_value(&c, start + 1);
        i = start + 1 + value.chars().count();
        let name = letter.to_string();
        if m.channel.contains(&name) || "XYZABCUVWQ".contains(letter) {
            out.push(Word::Axis(name, value.trim().to_string(), false));
        } else {
            out.push(Word::Letter(letter, value.trim().to_string()));
        }
    }
    Ok(out)
}

/// The value after an address: spaces, signs, digits and a point.
fn take_value(c: &[char], from: usize) -> String {
    let mut j = from;
    while j < c.len() && c[j] == ' ' {
        j += 1;
    }
    while j < c.len() && (c[j].is_ascii_digit() || "+-.".contains(c[j])) {
        j += 1;
    }
    c[from..j].iter().collect()
}

/// The block without comments: `(…)` nested, open to the end; `;` to the end.
fn strip(line: &str) -> String {
    let mut code = String::new();
    let mut depth = 0;
    for ch in line.chars() {
        match ch {
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            ';' if depth == 0 => break,
            _ if depth == 0 => code.push(ch),
            _ => {}
        }
    }
    code
}

/// The modal state as the program set it.
struct Modal {
    rapid: Option<bool>,
    incremental: Option<bool>,
    per_minute: bool,
    metric: bool,
    feed: Option<f64>,
    zero: usize,
    mcs: bool,
    ended: bool,
}

/// Runs `program` on `m`: the tested axis's machine positions, or the first refusal.
pub fn run(program: &str, m: &Isg) -> Result<Trace, Refusal> {
    let mut s = Modal {
        rapid: None,
        incremental: None,
        per_minute: false,
        metric: false,
        feed: None,
        zero: m.active,
        mcs: false,
        ended: false,
    };
    let mut axis = Tracker::new(m.initial);
    for (k, raw) in program.lines().enumerate() {
        let n = k + 1;
        let code = strip(raw);
        let code = code.trim();
        if code.is_empty() || (k == 0 && code.starts_with('%')) {
            continue;
        }
        if s.ended {
            return refuse(n, raw, "a block after the program's end");
        }
        let code = match code.strip_prefix('N') {
            Some(r) if r.starts_with(|c: char| c.is_ascii_digit()) => {
                r.trim_start_matches(|c: char| c.is_ascii_digit())
            }
            _ => code,
        };
        let ws = words(n, raw, code, m)?;
        block(m, &mut s, &mut axis, (n, raw), &ws)?;
    }
    if !s.ended {
        return refuse(0, "", "no M30 or M02 at the end");
    }
    Ok(axis.trace)
}

fn block(
    m: &Isg,
    s: &mut Modal,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    ws: &[Word],
) -> Result<(), Refusal> {
    if let [Word::Hash(h)] = ws {
        if let Some(rest) = h.strip_prefix("SUPPRESS OFFSETS") {
            return suppressed(m, s, axis, (n, raw), rest);
        }
        return hash(s, axis, (n, raw), h);
    }
    let dwell = ws
        .iter()
        .any(|w| matches!(w, Word::Letter('G', g) if number(g).is_some_and(|v| v.value == 4.0)));
    if dwell {
        return dwell_block(m, axis, (n, raw), ws);
    }
    let mut target = None;
    for w in ws {
        match w {
            Word::Letter('G', g) => g_code(s, g).or_else(|e| refuse(n, raw, e))?,
            Word::Letter('F', f) => match number(f) {
                Some(v) if !v.signed => s.feed = Some(v.value),
                _ => return refuse(n, raw, format!("`F{f}` is not a feed")),
            },
            Word::Letter('M', v) if matches!(v.as_str(), "30" | "02" | "2") => s.ended = true,
            Word::Letter(l, v) => {
                return refuse(n, raw, format!("`{l}{v}` is not modelled by this check"));
            }
            Word::Axis(name, value, long) if *name == m.axis => {
                target = Some((value.clone(), *long))
            }
            Word::Axis(name, value, _) if m.channel.contains(name) => {
                axis.other(n, format!("moves {name} to {value}"))
            }
            Word::Axis(name, value, _) => {
                return refuse(
                    n,
                    raw,
                    format!(
                        "`{name}{value}`: {name} is not an axis of the channel ({})",
                        m.channel.join(", ")
                    ),
                );
            }
            Word::Hash(h) => return refuse(n, raw, format!("#{h} with other words in its block")),
        }
    }
    let Some((value, long)) = target else {
        return Ok(());
    };
    let to = destination(m, s, axis.position(), &value, long).or_else(|e| refuse(n, raw, e))?;
    let feed = feed(s).or_else(|e| refuse(n, raw, e))?;
    axis.go(n, to, feed);
    Ok(())
}

/// `#SUPPRESS OFFSETS <axis positions>`: a motion block (modal G01/G00 and F) whose
/// positions take no offset, in G90 only (ID 20985); the offset types' list is not
/// modelled.
fn suppressed(
    m: &Isg,
    s: &mut Modal,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    rest: &str,
) -> Result<(), Refusal> {
    let rest = rest.trim();
    if rest.starts_with('[') {
        return refuse(
            n,
            raw,
            "#SUPPRESS OFFSETS with a list of offset types is not modelled",
        );
    }
    if s.incremental != Some(false) {
        return refuse(
            n,
            raw,
            "#SUPPRESS OFFSETS only in absolute programming, G90 (ID 20985)",
        );
    }
    let ws = words(n, raw, rest, m)?;
    if ws.is_empty() || !ws.iter().all(|w| matches!(w, Word::Axis(..))) {
        return refuse(n, raw, "#SUPPRESS OFFSETS takes axis positions only");
    }
    let mcs = std::mem::replace(&mut s.mcs, true);
    let moved = block(m, s, axis, (n, raw), &ws);
    s.mcs = mcs;
    moved
}

fn g_code(s: &mut Modal, g: &str) -> Result<(), String> {
    let v = number(g)
        .filter(|v| !v.signed && v.value.fract() == 0.0)
        .ok_or(format!("G{g} is not modelled"))?;
    match v.value as u32 {
        0 => s.rapid = Some(true),
        1 => s.rapid = Some(false),
        17..=19 | 40 => {}
        71 => s.metric = true,
        70 => return Err("inch input".into()),
        90 => s.incremental = Some(false),
        91 => s.incremental = Some(true),
        94 => s.per_minute = true,
        95 => return Err("feed per revolution: the plan's feed is per minute".into()),
        53 => s.zero = 0,
        c @ 54..=59 => s.zero = (c - 53) as usize,
        92 => return Err("G92 sets a reference point offset: it changes offsets".into()),
        c => return Err(format!("G{c} is not modelled by this check")),
    }
    Ok(())
}

fn hash(
    s: &mut Modal,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    h: &str,
) -> Result<(), Refusal> {
    match h {
        "MCS ON" => s.mcs = true,
        "MCS OFF" => s.mcs = false,
        _ => match h.strip_prefix("TIME ").and_then(number) {
            Some(t) if !t.signed => axis.dwell(n, t.value),
            _ => return refuse(n, raw, format!("#{h} is not modelled by this check")),
        },
    }
    Ok(())
}

/// `G04 <first main axis><s>`, alone.
fn dwell_block(
    m: &Isg,
    axis: &mut Tracker,
    (n, raw): (usize, &str),
    ws: &[Word],
) -> Result<(), Refusal> {
    let first = m.channel.first().map(String::as_str).unwrap_or("X");
    match ws {
        [Word::Letter('G', _), Word::Axis(name, v, false)] if name == first => match number(v) {
            Some(t) if !t.signed => {
                axis.dwell(n, t.value);
                Ok(())
            }
            _ => refuse(n, raw, "G04's time is a plain number of seconds"),
        },
        _ => refuse(
            n,
            raw,
            format!("the dwell is `G04 {first}<s>` alone in its block"),
        ),
    }
}

fn feed(s: &Modal) -> Result<Feed, String> {
    if !s.metric {
        return Err("a move before G71 (metric) is set".into());
    }
    match s.rapid {
        None => Err("a move before G00/G01 is set".into()),
        Some(true) => Ok(Feed::Rapid),
        Some(false) if !s.per_minute => Err("a feed move before G94".into()),
        Some(false) => s
            .feed
            .map(Feed::PerMinute)
            .ok_or_else(|| "a feed move before F".into()),
    }
}

/// The machine position an axis word takes the axis to.
fn destination(m: &Isg, s: &Modal, at: f64, value: &str, long: bool) -> Result<f64, String> {
    let incremental = s.incremental.ok_or("a move before G90/G91 is set")?;
    let signs = value.chars().take_while(|c| "+-".contains(*c)).count();
    let num =
        number(&value[signs.saturating_sub(1)..]).ok_or(format!("`{value}` is not a number"))?;
    if signs > 1 && (!m.modulo || incremental) {
        return Err("two signs: only for an absolute position on a modulo axis (ID 20958)".into());
    }
    if incremental {
        return Ok(at + num.value);
    }
    let offset = if s.mcs { 0.0 } else { m.zero[s.zero] };
    if !m.modulo {
        return Ok(num.value + offset);
    }
    if long && num.signed {
        return Err("direction signs are not supported after a long axis name".into());
    }
    let position = if signs > 1 {
        number(&value[1..]).map_or(0.0, |v| v.value)
    } else {
        num.value.abs()
    };
    let here = turn(at - offset);
    let up = turn(turn(position) - here);
    let by = match value.chars().next() {
        Some('+') => up,
        Some('-') if up == 0.0 => 0.0,
        Some('-') => up - 360.0,
        _ if up > 180.0 => up - 360.0,
        _ => up,
    };
    Ok(at + by)
}

#[cfg(test)]
mod tests {
    use super::super::machine::{turn, verify};
    use super::super::{expect, small_plan};
    use super::*;
    use axcheck::units::AxisKind;

    fn isg(channel: &[&str], axis: &str) -> Isg {
        Isg {
            channel: channel.iter().map(|a| a.to_string()).collect(),
            axis: axis.to_string(),
            zero: [0.0, 107.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            active: 1,
            modulo: false,
            initial: 0.0,
        }
    }

    /// The small plan with today's head (`G53`: zero offset deselected).
    const G53: &str = "% TEST\nG17 G71 G90 G94 G40 G53\nG01 X6.000 F1500.000 ; start\nG01 X10.000 (T1 up)\n#TIME 2.500\nN40 G01 X50.000\nG04 X2.5\nG01 X54.000\nG01 X50.000\n#TIME 2.500\nG01 X10.000\n#TIME 2.500\nM30\n";

    #[test]
    fn g53_deselects_the_zero_offset() {
        let trace = run(G53, &isg(&["X", "Y", "Z"], "X")).unwrap();
        let plan = small_plan(AxisKind::Linear);
        assert_eq!(
            verify(&plan, &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
        let g54 = run(&G53.replace("G53", "G54"), &isg(&["X", "Y", "Z"], "X")).unwrap();
        assert_eq!(g54.readings[0].position, 117.0);
        let mcs = G53
            .replace("G40 G53", "G40 G54\n#MCS ON")
            .replace("M30", "#MCS OFF\nM30");
        let trace = run(&mcs, &isg(&["X", "Y", "Z"], "X")).unwrap();
        assert_eq!(
            verify(&plan, &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
    }

    /// The small plan as today's writer puts it for `--axis X1`: `X16.000` for 6 mm,
    /// `X110.000` for 10 mm.
    const X1_TODAY: &str = "% TEST\nG17 G71 G90 G94 G40 G53\nG01 X16.000 F1500.000\nG01 X110.000\n#TIME 2.500\nG01 X150.000\n#TIME 2.500\nG01 X154.000\nG01 X150.000\n#TIME 2.500\nG01 X110.000\n#TIME 2.500\nM30\n";

    #[test]
    fn suppress_offsets_moves_in_machine_coordinates() {
        let program = G53
            .replace("G40 G53", "G40 G54")
            .replace("G01 X", "#SUPPRESS OFFSETS X")
            .replace(
                "#SUPPRESS OFFSETS X6.000 F1500.000",
                "G01 F1500.000\n#SUPPRESS OFFSETS X6.000",
            );
        let trace = run(&program, &isg(&["X", "Y", "Z"], "X")).unwrap();
        let plan = small_plan(AxisKind::Linear);
        assert_eq!(
            verify(&plan, &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
        let e = run(&program.replace("G90", "G91"), &isg(&["X", "Y", "Z"], "X")).unwrap_err();
        assert!(e.why.contains("ID 20985"), "{e}");
    }

    /// Today's `G01 X110.000` for X1 = 10 mm: axis X at 110. Refused where the channel has
    /// no X; where it has one, X moves and X1 never does.
    #[test]
    fn x110_is_axis_x_at_110_not_x1_at_10() {
        let e = run(X1_TODAY, &isg(&["X1", "Y", "Z"], "X1")).unwrap_err();
        assert_eq!((e.line, e.block.as_str()), (3, "G01 X16.000 F1500.000"));
        assert!(
            e.why.contains("X is not an axis of the channel (X1, Y, Z)"),
            "{e}"
        );
        let both = run(X1_TODAY, &isg(&["X", "X1", "Z"], "X1")).unwrap();
        assert_eq!(both.others[1], "line 4: moves X to 110.000");
        assert!(both.moves.is_empty());
        let plan = small_plan(AxisKind::Linear);
        assert_eq!(verify(&plan, &both, &expect(0.0, false)).len(), 4 + 2 + 6);
        let right = X1_TODAY
            .replace("X110", "X1=10")
            .replace("X16", "X1=6")
            .replace("X150", "X1 = 50")
            .replace("X154", "X1=54");
        let trace = run(&right, &isg(&["X1", "Y", "Z"], "X1")).unwrap();
        assert_eq!(
            verify(&plan, &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
    }

    /// Today's `C25.000` for C2 = 5°.
    #[test]
    fn c25_is_not_c2_at_5() {
        let program = "%T\nG71 G90 G94 G53\nG01 C25.000 F1500.000\nM30\n";
        let e = run(program, &isg(&["X", "Y", "C2"], "C2")).unwrap_err();
        assert!(e.why.contains("C is not an axis of the channel"), "{e}");
        let trace = run(
            &program.replace("C25", "C2=5"),
            &isg(&["X", "Y", "C2"], "C2"),
        )
        .unwrap();
        assert_eq!(trace.moves[0].to, 5.0);
    }

    /// Today's rotary start `G90 G01 C-5.000` on a modulo axis: 5° reached turning
    /// negative, so every later (incremental) target is 10° from its label.
    #[test]
    fn c_minus_5_on_a_modulo_axis_is_plus_5() {
        let m = Isg {
            modulo: true,
            zero: [0.0; 7],
            ..isg(&["X", "C"], "C")
        };
        let program = "%T\nG71 G90 G94 G53\nG01 C-5.000 F1500.000\nG91\nG01 C5.000\n#TIME 2.5\nG01 C-10.000\nG90\nG01 C355.000\nG01 C+-200\nM30\n";
        let trace = run(program, &m).unwrap();
        let to: Vec<f64> = trace.moves.iter().map(|m| turn(m.to)).collect();
        assert_eq!(to, [5.0, 10.0, 0.0, 355.0, 160.0]);
        assert_eq!(trace.moves[0].to, -355.0);
        let e = run(&program.replace("G01 C-10.000", "G01 C+-10.000"), &m).unwrap_err();
        assert!(e.why.contains("ID 20958"), "{e}");
    }
}
