//! A SINUMERIK 840D sl main program in Siemens mode, read strictly: each block tokenized,
//! words the check does not model refused, the tested axis simulated in machine
//! coordinates through the frames, SUPA/G153/G53, incremental moves, a modulo rotary
//! axis and diameter programming.
//!
//! Rules and their sources:
//! - `;` starts a comment to the end of the block; `N…` or `:…` numbers a block; a first
//!   line `%_N_NAME_MPF` is the punch-tape header (SINUMERIK ONE NC Programming 12/2019,
//!   6FC5398-2EP40-0BA0, §2.2, p. 43; special characters: 840Di sl Fundamentals 11/2006
//!   p. 50).
//! - An address of more than one letter, or with a numeric extension (`X1`), takes its
//!   value after `=`; a numeric extension must be followed by `=`, `(`, `[`, … so `X110.000`
//!   is X = 110 (840D Fundamentals Programming Manual 10.2004, 6FC5 298-7AB00-0BP1, p. 2-13).
//!   An axis not in the channel is refused.
//! - `G4 F…` dwells in seconds (`G4 S…` in spindle revolutions, refused) in a block of its
//!   own (the ISO dialect's rule, ISO Milling 04.07 §3.3.1; for Siemens mode the same rule
//!   is quoted from secondary sources: unconfirmed).
//! - Frames: SUPA suppresses all frames, the external zero offset and DRF; G153 all frames;
//!   G53 the settable and programmable frames; all non-modal. G500 deselects the settable
//!   frame, the base frame stays (840D sl/828D Basic Functions K2, 09/2011, §10.5, p. 741;
//!   ISO Milling 04.07 §3.1.1).
//! - A 360° modulo rotary axis: with MD30455 bit 0 = 0 an absolute value outside
//!   [0, 360) is refused (alarm 16830: a third-party description, not a Siemens manual);
//!   with bit 0 = 1 it is taken modulo 360. G90 moves as AC (positive if the target is
//!   above the position, negative if below) with MD30455 bit 2 = 0, the shorter way (DC)
//!   with bit 2 = 1 (Axes and spindles Function Manual 06/2019, A5E47437747B AA, §7.2,
//!   p. 225). `=ACP(…)`/`=ACN(…)` force the direction, `=DC(…)` the shorter way,
//!   `=IC(…)` and G91 move by the value (808D Programming 05/2012 p. 26).
//! - DIAMON: the transverse axis's absolute and incremental values are diameters; DIAM90:
//!   absolute diameters, incremental radii; DIAMOF: radii (808D Programming 05/2012 p. 26).
//! - Units, feed mode, G90/G91 and G0/G1 are initial settings of machine data: a move
//!   before the program set them is refused. G70/G700 (inch) and G95 are refused.

use super::machine::{Feed, Refusal, Trace, Tracker, number, refuse, turn};

/// A 360° modulo rotary axis's machine data.
#[derive(Debug, Clone, Copy)]
pub struct Modulo {
    /// MD30455 bit 0: absolute values outside [0, 360) taken modulo 360 (else refused).
    pub wrap_values: bool,
    /// MD30455 bit 2: G90 takes the shorter way (else AC: by the sign of the difference).
    pub shortest: bool,
}

/// The machine the program runs on.
#[derive(Debug, Clone)]
pub struct Sinumerik {
    /// The channel's axis names; the tested one.
    pub channel: Vec<String>,
    pub axis: String,
    /// The base frame, the settable frames G54..G57 and the external zero offset of the
    /// tested axis; the settable frame active at the start (`None`: G500).
    pub base: f64,
    pub settable: [f64; 4],
    pub active: Option<usize>,
    pub external: f64,
    /// `None`: a linear axis or a rotary axis without modulo.
    pub modulo: Option<Modulo>,
    /// The tested axis is a lathe's transverse axis; DIAMON at the start (MD20150).
    pub transverse: bool,
    pub diamon: bool,
    pub initial: f64,
}

/// A token of a block.
#[derive(Debug, Clone, PartialEq)]
enum Token {
    /// `X10.5`, `G1`, `F1000`: one address letter and a number.
    Word(char, f64, String),
    /// `X1=10`, `C=ACP(355)`: a name, the function (`""`, `IC`, `AC`, `ACP`, `ACN`, `DC`).
    Assign(String, String, f64),
    /// `SUPA`, `DIAMON`.
    Keyword(String),
}

/// Diameter mode of the transverse axis.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Diam {
    On,
    Off,
    Abs,
}

/// The words without a value this check models.
const KEYWORDS: &[&str] = &["SUPA", "DIAMON", "DIAMOF", "DIAM90"];

fn tokens(n: usize, line: &str, code: &str) -> Result<Vec<Token>, Refusal> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let is_name = |ch: char| ch.is_ascii_uppercase() || ch.is_ascii_digit() || ch == '_';
    while i < c.len() {
        if c[i] == ' ' || c[i] == '\t' {
            i += 1;
            continue;
        }
        if !c[i].is_ascii_uppercase() {
            return refuse(n, line, format!("`{}` where a word begins", c[i]));
        }
        let start = i;
        while i < c.len() && is_name(c[i]) {
            i += 1;
        }
        let ident: String = c[start..i].iter().collect();
        while i < c.len() && c[i] == ' ' {
            i += 1;
        }
        if i < c.len() && c[i] == '=' {
            let end = c[i + 1..]
                .iter()
                .position(|ch| *ch == ' ')
                .map_or(c.len(), |p| i + 1 + p);
            let value: String = c[i + 1..end].iter().collect();
            let (f, v) = assigned(&value).ok_or_else(|| Refusal {
                line: n,
                block: line.trim().into(),
                why: format!("`{ident}={value}` is not a value this check models"),
            })?;
            out.push(Token::Assign(ident, f, v));
            i = end;
            continue;
        }
        if KEYWORDS.contains(&ident.as_str()) {
            out.push(Token::Keyword(ident));
            continue;
        }
        let letters = ident
            .chars()
            .take_while(|ch| ch.is_ascii_uppercase())
            .count();
        let mut end = start + letters;
        while end < c.len() && (c[end].is_ascii_digit() || "+-.".contains(c[end])) {
            end += 1;
        }
        let text: String = c[start + letters..end].iter().collect();
        if text.is_empty() {
            out.push(Token::Keyword(ident));
            continue;
        }
        let address: String = c[start..start + letters].iter().collect();
        let num = match (address.len(), number(&text)) {
            (1, Some(num)) => num,
            _ => {
                return refuse(
                    n,
                    line,
                    format!("`{address}{text}`: an address of more than one letter takes `=`"),
                );
            }
        };
        out.push(Token::Word(c[start], num.value, format!("{address}{text}")));
        i = end;
    }
    Ok(out)
}

/// `10.5`, `IC(-5)`, `ACP(355.000)` → function and value.
fn assigned(text: &str) -> Option<(String, f64)> {
    if let Some(num) = number(text) {
        return Some((String::new(), num.value));
    }
    let (f, rest) = text.split_once('(')?;
    let inner = rest.strip_suffix(')')?;
    let ok = matches!(f, "IC" | "AC" | "ACP" | "ACN" | "DC");
    ok.then(|| number(inner).map(|num| (f.to_string(), num.value)))?
}

/// The modal state as the program set it (`None`: left to machine data).
struct Modal {
    rapid: Option<bool>,
    incremental: Option<bool>,
    per_minute: bool,
    metric: bool,
    feed: Option<f64>,
    settable: Option<usize>,
    diam: Diam,
    ended: bool,
}

/// Runs `program` on `m`: the tested axis's machine positions, or the first refusal.
pub fn run(program: &str, m: &Sinumerik) -> Result<Trace, Refusal> {
    let mut state = Modal {
        rapid: None,
        incremental: None,
        per_minute: false,
        metric: false,
        feed: None,
        settable: m.active,
        diam: if m.diamon { Diam::On } else { Diam::Off },
        ended: false,
    };
    let mut axis = Tracker::new(m.initial);
    for (k, raw) in program.lines().enumerate() {
        let n = k + 1;
        let code = raw.split(';').next().unwrap_or("").trim();
        if code.is_empty() || (k == 0 && header(code)) {
            continue;
        }
        if state.ended {
            return refuse(n, raw, "a block after the program's end");
        }
        let code = block_number(code);
        let ts = tokens(n, raw, code)?;
        block(m, &mut state, &mut axis, (n, raw), &ts)?;
    }
    if !state.ended {
        return refuse(0, "", "no M30, M2 or M17 at the end");
    }
    Ok(axis.trace)
}

/// `%_N_NAME_MPF`.
fn header(code: &str) -> bool {
    code.strip_prefix("%_N_")
        .and_then(|r| r.strip_suffix("_MPF"))
        .is_some_and(|name| {
            !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        })
}

/// The block without its number (`N10 `, `:10 `).
fn block_number(code: &str) -> &str {
    for p in ['N', ':'] {
        if let Some(rest) = code.strip_prefix(p) {
            let digits = rest.chars().take_while(|c| c.is_ascii_digit()).count();
            if digits > 0 {
                return rest[digits..].trim_start();
            }
        }
    }
    code
}

/// Which frames a block suppresses.
#[derive(Clone, Copy, PartialEq)]
enum Suppress {
    None,
    Settable,
    AllFrames,
    All,
}

fn block(
    m: &Sinumerik,
    state: &mut Modal,
    axis: &mut Tracker,
    (n, line): (usize, &str),
    ts: &[Token],
) -> Result<(), Refusal> {
    let mut suppress = Suppress::None;
    let mut dwell = ts
        .iter()
        .any(|t| matches!(t, Token::Word('G', g, _) if *g == 4.0));
    let mut target = None;
    for t in ts {
        match t {
            Token::Word('G', g, _) => {
                g_code(*g, state, &mut suppress, &mut dwell).or_else(|e| refuse(n, line, e))?
            }
            Token::Word('M', _, text) if matches!(text.as_str(), "M2" | "M02" | "M30" | "M17") => {
                state.ended = true
            }
            Token::Word('M' | 'S' | 'T' | 'D' | 'H', _, text) => {
                return refuse(n, line, format!("`{text}` is not modelled by this check"));
            }
            Token::Word('F', v, _) => {
                if !dwell {
                    state.feed = Some(*v);
                }
            }
            Token::Assign(name, f, v) if name == "F" && f.is_empty() => {
                if !dwell {
                    state.feed = Some(*v);
                }
            }
            Token::Keyword(k) => {
                keyword(k, state, &mut suppress).or_else(|e| refuse(n, line, e))?
            }
            Token::Word(a, v, text) => {
                target = axis_word(m, axis, n, &a.to_string(), "", *v, text)
                    .or_else(|e| refuse(n, line, e))?
                    .or(target)
            }
            Token::Assign(name, f, v) => {
                target = axis_word(m, axis, n, name, f, *v, name)
                    .or_else(|e| refuse(n, line, e))?
                    .or(target)
            }
        }
    }
    if dwell {
        return dwell_block(axis, (n, line), ts);
    }
    let Some((f, v)) = target else {
        return Ok(());
    };
    let to =
        destination(m, state, axis.position(), suppress, &f, v).or_else(|e| refuse(n, line, e))?;
    let feed = feed(state).or_else(|e| refuse(n, line, e))?;
    axis.go(n, to, feed);
    Ok(())
}

fn g_code(g: f64, s: &mut Modal, sup: &mut Suppress, dwell: &mut bool) -> Result<(), String> {
    if g.fract() != 0.0 {
        return Err(format!("G{g} is not modelled"));
    }
    match g as u32 {
        0 => s.rapid = Some(true),
        1 => s.rapid = Some(false),
        4 => *dwell = true,
        9 | 17..=19 | 40 | 60 | 64 => {}
        71 | 710 => s.metric = true,
        70 | 700 => return Err("inch input".into()),
        90 => s.incremental = Some(false),
        91 => s.incremental = Some(true),
        94 => s.per_minute = true,
        95 => return Err("feed per revolution: the plan's feed is per minute".into()),
        53 => *sup = Suppress::Settable,
        153 => *sup = Suppress::AllFrames,
        500 => s.settable = None,
        c @ 54..=57 => s.settable = Some((c - 54) as usize),
        c => return Err(format!("G{c} is not modelled by this check")),
    }
    Ok(())
}

fn keyword(k: &str, s: &mut Modal, sup: &mut Suppress) -> Result<(), String> {
    match k {
        "SUPA" => *sup = Suppress::All,
        "DIAMON" => s.diam = Diam::On,
        "DIAMOF" => s.diam = Diam::Off,
        "DIAM90" => s.diam = Diam::Abs,
        _ => return Err(format!("`{k}` is not modelled by this check")),
    }
    Ok(())
}

/// The tested axis's word: `Some((function, slide value))`; another channel axis is a
/// move of another axis; a name not in the channel is refused.
fn axis_word(
    m: &Sinumerik,
    axis: &mut Tracker,
    n: usize,
    name: &str,
    f: &str,
    v: f64,
    text: &str,
) -> Result<Option<(String, f64)>, String> {
    if name == m.axis {
        return Ok(Some((f.to_string(), v)));
    }
    if m.channel.iter().any(|a| a == name) {
        axis.other(n, format!("moves {text}"));
        return Ok(None);
    }
    Err(format!(
        "`{text}`: {name} is not an axis of the channel ({})",
        m.channel.join(", ")
    ))
}

fn dwell_block(axis: &mut Tracker, (n, line): (usize, &str), ts: &[Token]) -> Result<(), Refusal> {
    let time: Vec<f64> = ts
        .iter()
        .filter_map(|t| match t {
            Token::Word('F', v, _) => Some(*v),
            Token::Assign(name, f, v) if name == "F" && f.is_empty() => Some(*v),
            _ => None,
        })
        .collect();
    if ts.len() != 2 || time.len() != 1 {
        return refuse(n, line, "G4 F… (seconds) in a block of its own");
    }
    axis.dwell(n, time[0]);
    Ok(())
}

fn feed(s: &Modal) -> Result<Feed, String> {
    if !s.metric {
        return Err("a move before G71 (metric) is set".into());
    }
    match s.rapid {
        None => Err("a move before G0/G1 is set".into()),
        Some(true) => Ok(Feed::Rapid),
        Some(false) if !s.per_minute => Err("a feed move before G94".into()),
        Some(false) => s
            .feed
            .map(Feed::PerMinute)
            .ok_or_else(|| "a feed move before F".into()),
    }
}

/// The machine position the word takes the axis to.
fn destination(
    m: &Sinumerik,
    s: &Modal,
    at: f64,
    sup: Suppress,
    f: &str,
    v: f64,
) -> Result<f64, String> {
    let incremental = match f {
        "IC" => true,
        "" => s.incremental.ok_or("a move before G90/G91 is set")?,
        _ => false,
    };
    let half = m.transverse && (s.diam == Diam::On || (s.diam == Diam::Abs && !incremental));
    let v = if half { v / 2.0 } else { v };
    if incremental {
        return Ok(at + v);
    }
    let settable = s.settable.map_or(0.0, |k| m.settable[k]);
    let frames = match sup {
        Suppress::All => 0.0,
        Suppress::AllFrames => m.external,
        Suppress::Settable => m.base + m.external,
        Suppress::None => m.base + settable + m.external,
    };
    let Some(md) = m.modulo else {
        if !f.is_empty() && f != "AC" {
            return Err(format!("{f}(…) on an axis without modulo"));
        }
        return Ok(v + frames);
    };
    let v = if (0.0..360.0).contains(&v) {
        v
    } else if md.wrap_values && f.is_empty() {
        turn(v)
    } else {
        return Err(format!(
            "{v} outside [0, 360) on a modulo axis: alarm 16830 (MD30455 bit 0 = 0)"
        ));
    };
    let here = turn(at - frames);
    let up = turn(v - here);
    let down = up - 360.0;
    let shortest = if up <= 180.0 { up } else { down };
    Ok(at
        + match f {
            "ACP" => up,
            "ACN" if up == 0.0 => 0.0,
            "ACN" => down,
            "DC" => shortest,
            _ if md.shortest && f.is_empty() => shortest,
            _ => v - here,
        })
}

#[cfg(test)]
mod tests {
    use super::super::machine::{turn, verify};
    use super::super::{expect, small_plan};
    use super::*;
    use axcheck::units::AxisKind;

    /// A channel X, Y, Z (or `axis`) with a base frame of 100 and G54 = 7 on the tested
    /// axis, G54 active.
    fn machine(axis: &str) -> Sinumerik {
        Sinumerik {
            channel: vec![axis.to_string(), "Y".into(), "Z".into()],
            axis: axis.to_string(),
            base: 100.0,
            settable: [7.0, 0.0, 0.0, 0.0],
            active: Some(0),
            external: 0.0,
            modulo: None,
            transverse: false,
            diamon: false,
            initial: 0.0,
        }
    }

    /// The small plan in machine coordinates (SUPA in each motion block).
    const SUPA: &str = "; %_N_TEST_MPF\nG17 G71 G90 G94 G40 G60\nG1 SUPA X6.000 F1500.000\nSUPA X10.000\nG4 F2.500\nSUPA X50.000\nG4 F2.500\nSUPA X54.000\nSUPA X50.000\nG4 F2.5\nN100 SUPA X10.000 ; T1 down\nG4 F2.500\nM30\n";

    #[test]
    fn supa_moves_in_machine_coordinates_at_the_feed() {
        let trace = run(SUPA, &machine("X")).unwrap();
        let plan = small_plan(AxisKind::Linear);
        assert_eq!(
            verify(&plan, &trace, &expect(0.0, false)),
            Vec::<String>::new()
        );
    }

    /// Today's `G500`: the settable frame goes, the base frame stays; G53 keeps it too.
    #[test]
    fn g500_and_g53_keep_the_base_frame() {
        let program = SUPA.replace("G60", "G60 G500").replace("SUPA ", "");
        let trace = run(&program, &machine("X")).unwrap();
        assert_eq!(trace.readings[0].position, 110.0);
        let trace = run(&SUPA.replace("SUPA", "G53"), &machine("X")).unwrap();
        assert_eq!(trace.readings[0].position, 110.0);
        let trace = run(&SUPA.replace("SUPA", "G153"), &machine("X")).unwrap();
        assert_eq!(trace.readings[0].position, 10.0);
        let trace = run(&SUPA.replace("SUPA ", ""), &machine("X")).unwrap();
        assert_eq!(trace.readings[0].position, 117.0);
    }

    /// `X110.000` is X = 110, not X1 = 10: refused when X is not a channel axis.
    #[test]
    fn an_extended_address_needs_its_equals_sign() {
        let program = "G17 G71 G90 G94\nG1 X110.000 F1500.000\nM30\n";
        let e = run(program, &machine("X1")).unwrap_err();
        assert!(
            e.why.contains("X is not an axis of the channel (X1, Y, Z)"),
            "{e}"
        );
        let trace = run(&program.replace("X110", "X1=10"), &machine("X1")).unwrap();
        assert_eq!(trace.moves[0].to, 117.0);
        let e = run(&program.replace("X110.000", "X1 10.000"), &machine("X1")).unwrap_err();
        assert!(e.why.contains("`1` where a word begins"), "{e}");
    }

    /// Today's rotary start `G1 C-5.000` on a modulo axis: alarm 16830 with MD30455 bit 0
    /// = 0; with bit 0 = 1 it is 355°, and G90 moves as AC (downwards from 0°).
    #[test]
    fn a_negative_absolute_position_on_a_modulo_axis_is_refused() {
        let rotary = |wrap_values| Sinumerik {
            modulo: Some(Modulo {
                wrap_values,
                shortest: false,
            }),
            base: 0.0,
            settable: [0.0; 4],
            ..machine("C")
        };
        let program = "G17 G71 G90 G94\nG1 C-5.000 F1500.000\nG91\nC5.000\nG4 F2.5\nM30\n";
        let e = run(program, &rotary(false)).unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.why.contains("alarm 16830"), "{e}");
        let trace = run(program, &rotary(true)).unwrap();
        assert_eq!(trace.moves[0].to, 355.0);
        assert_eq!(turn(trace.readings[0].position), 0.0);
        let forced = run(
            &program.replace("C-5.000", "C=ACN(355.000)"),
            &rotary(false),
        )
        .unwrap();
        assert_eq!(forced.moves[0].to, -5.0);
    }

    /// DIAMON: X in diameter; DIAM90: absolute diameters, incremental radii.
    #[test]
    fn diameter_programming() {
        let lathe = Sinumerik {
            transverse: true,
            base: 0.0,
            settable: [0.0; 4],
            ..machine("X")
        };
        let program = "G18 G71 G90 G94 DIAMON\nG1 X20.000 F1500.000\nG91 X4.000\nDIAM90\nX4.000\nG4 F2.5\nM30\n";
        let trace = run(program, &lathe).unwrap();
        let to: Vec<f64> = trace.moves.iter().map(|m| m.to).collect();
        assert_eq!(to, [10.0, 12.0, 16.0]);
        let e = run(&program.replace("G4 F2.5", "G4 F2.5 X1.0"), &lathe).unwrap_err();
        assert!(e.why.contains("block of its own"), "{e}");
    }
}
