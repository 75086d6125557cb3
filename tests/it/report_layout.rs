//! Reports that never overprint: every PDF of the example campaign and of the names campaign
//! (`tests/data/names/`: a 78-character campaign name, a 10 000-character machine name,
//! Cyrillic, CJK, Hebrew and Arabic names) read back with `pdftotext -bbox`, and each page
//! checked as a reader's eye would: no two words' ink on one another, nothing off the page,
//! nothing of the body in the footer's band.
//!
//! A word's box from pdftotext spans its font's ascender to its descender, more than the
//! ink: lines set closer than that (the per-target table, a number over its label in the
//! summary's boxes) touch without any glyph touching. The check uses the body of the
//! letters, from the cap height to half the descender (Inter: ascender 0.969 em, cap height
//! 0.727 em, descender 0.242 em), where two words of different lines cannot meet without
//! their letters meeting; words in the fallback faces (Hebrew, Arabic, CJK) are measured
//! by their face's metrics ([`Face`]).

use crate::common::axcheck;
use std::path::{Path, PathBuf};

/// A word as pdftotext places it (points, y down).
#[derive(Debug, Clone)]
struct Word {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
    text: String,
}

/// A face's vertical metrics, in em: pdftotext's box of a word spans `ascender` above the
/// baseline to `descender` below it; the letters' body `top` above it to `bottom` below.
struct Face {
    ascender: f64,
    descender: f64,
    top: f64,
    bottom: f64,
}

/// Inter: cap height to half the descender.
const INTER: Face = Face {
    ascender: 0.969,
    descender: 0.242,
    top: 0.727,
    bottom: 0.121,
};
/// Noto Sans Arabic (templates/fonts): alef's height, half the deepest letter (ي, 0.42 em).
const ARABIC: Face = Face {
    ascender: 1.374,
    descender: 0.738,
    top: 0.714,
    bottom: 0.21,
};
/// Noto Sans Hebrew: the letters' height, half the descender of ק ך ן (0.19 em).
const HEBREW: Face = Face {
    ascender: 1.068,
    descender: 0.292,
    top: 0.603,
    bottom: 0.096,
};
/// Droid Sans Fallback: an ideograph's whole ink (0.10 em below the baseline to 0.82).
const CJK: Face = Face {
    ascender: 0.766,
    descender: 0.238,
    top: 0.82,
    bottom: 0.10,
};

impl Word {
    /// The face the word is set in, by its letters: the embedded fallbacks set what Inter
    /// lacks.
    fn face(&self) -> &'static Face {
        let any = |range: &[(u32, u32)]| {
            (self.text.chars()).any(|c| range.iter().any(|(a, b)| (*a..=*b).contains(&(c as u32))))
        };
        if any(&[
            (0x600, 0x6FF),
            (0x750, 0x77F),
            (0x8A0, 0x8FF),
            (0xFB50, 0xFDFF),
            (0xFE70, 0xFEFF),
        ]) {
            &ARABIC
        } else if any(&[(0x590, 0x5FF), (0xFB1D, 0xFB4F)]) {
            &HEBREW
        } else if any(&[(0x2E80, 0x9FFF), (0xF900, 0xFAFF), (0xFF00, 0xFFEF)]) {
            &CJK
        } else {
            &INTER
        }
    }

    /// The font size (points).
    fn size(&self) -> f64 {
        let face = self.face();
        (self.y1 - self.y0) / (face.ascender + face.descender)
    }

    fn baseline(&self) -> f64 {
        self.y0 + self.face().ascender * self.size()
    }

    /// The box of the letters' main body (see [`Face`]). Full-width punctuation at a
    /// word's end has its ink in one half of its em: Typst sets two of them side by side
    /// (`）：`) in one em, as Chinese typesetting does, so the other half is no ink.
    fn ink(&self) -> (f64, f64, f64, f64) {
        let (face, size, baseline) = (self.face(), self.size(), self.baseline());
        let top = baseline - face.top * size;
        let half = |c: Option<char>| c.is_some_and(|c| "（）：。，；、“”".contains(c));
        let x0 = self.x0
            + if half(self.text.chars().next()) {
                size / 2.0
            } else {
                0.0
            };
        let x1 = self.x1
            - if half(self.text.chars().last()) {
                size / 2.0
            } else {
                0.0
            };
        (x0, top, x1, baseline + face.bottom * size)
    }
}

struct Page {
    width: f64,
    height: f64,
    words: Vec<Word>,
}

/// The bottom margin of every report (`setup` in templates/style.typ): the footer's band.
const FOOTER_BAND: f64 = 17.0 / 25.4 * 72.0;
/// Overlaps smaller than this (points) are rounding.
const SLACK: f64 = 0.25;

fn attr(tag: &str, name: &str) -> f64 {
    let start = tag.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
    let end = start + tag[start..].find('"').unwrap();
    tag[start..end].parse().unwrap()
}

fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// The pages of `pdf` with their words, from `pdftotext -bbox`.
fn pages(pdf: &Path) -> Vec<Page> {
    let out = std::process::Command::new("pdftotext")
        .arg("-bbox")
        .arg(pdf)
        .arg("-")
        .output()
        .expect("pdftotext runs (.ci/test installs poppler-utils)");
    assert!(out.status.success(), "pdftotext {}", pdf.display());
    parse_bbox(&String::from_utf8_lossy(&out.stdout))
}

fn parse_bbox(html: &str) -> Vec<Page> {
    let mut pages = Vec::new();
    for line in html.lines().map(str::trim) {
        if line.starts_with("<page ") {
            pages.push(Page {
                width: attr(line, "width"),
                height: attr(line, "height"),
                words: Vec::new(),
            });
        } else if let Some(rest) = line.strip_prefix("<word ") {
            let (tag, text) = rest.split_once('>').unwrap();
            let text = text.strip_suffix("</word>").unwrap();
            pages.last_mut().unwrap().words.push(Word {
                x0: attr(tag, "xMin"),
                y0: attr(tag, "yMin"),
                x1: attr(tag, "xMax"),
                y1: attr(tag, "yMax"),
                text: unescape(text),
            });
        }
    }
    pages
}

/// The words of the footer: those in the band set as the page number is ("Page N of M":
/// its size, or its line for text in another face).
fn footer(page: &Page) -> Vec<bool> {
    let band = page.height - FOOTER_BAND;
    let number = page
        .words
        .iter()
        .rev()
        // "Page N of M", "Страница N из M", "第 N 页，共 M 页".
        .find(|w| matches!(w.text.as_str(), "Page" | "Страница" | "第") && w.y0 >= band);
    page.words
        .iter()
        .map(|w| {
            number.is_some_and(|n| {
                let same_size = (w.size() - n.size()).abs() < 0.15;
                let same_line = (w.baseline() - n.baseline()).abs() < 0.5;
                w.ink().1 >= band && (same_size || same_line)
            })
        })
        .collect()
}

/// What a reader would see as overprinted or cut on the pages of `pages`: words whose ink
/// meets, words off the page, the body in the footer's band.
fn problems(pages: &[Page]) -> Vec<String> {
    let mut found = Vec::new();
    for (p, page) in pages.iter().enumerate() {
        let p = p + 1;
        let band = page.height - FOOTER_BAND;
        let in_footer = footer(page);
        for (w, footer) in page.words.iter().zip(&in_footer) {
            let off = w.x0 < -SLACK
                || w.y0 < -SLACK
                || w.x1 > page.width + SLACK
                || w.y1 > page.height + SLACK;
            if off {
                found.push(format!("page {p}: {:?} leaves the page: {w:?}", w.text));
            } else if !footer && w.ink().3 > band + SLACK {
                found.push(format!(
                    "page {p}: {:?} runs into the footer (ink to y {:.1} pt, footer from {band:.1} pt)",
                    w.text,
                    w.ink().3
                ));
            }
        }
        // Sorted by the ink's top: a word meets only those that start above its bottom.
        let mut boxes: Vec<(f64, f64, f64, f64, &str)> = (page.words.iter())
            .filter(|w| w.x1 - w.x0 > SLACK)
            .map(|w| {
                let (a, b, c, d) = w.ink();
                (a, b, c, d, w.text.as_str())
            })
            .collect();
        boxes.sort_by(|a, b| a.1.total_cmp(&b.1));
        for (i, a) in boxes.iter().enumerate() {
            for b in boxes[i + 1..].iter().take_while(|b| b.1 < a.3 - SLACK) {
                let x = a.2.min(b.2) - a.0.max(b.0);
                let y = a.3.min(b.3) - a.1.max(b.1);
                if x > SLACK && y > SLACK {
                    found.push(format!(
                        "page {p}: {:?} at ({:.1}, {:.1}) overprints {:?} at ({:.1}, {:.1})",
                        a.4, a.0, a.1, b.4, b.0, b.1
                    ));
                }
            }
        }
    }
    found
}

fn pdfs(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            out.extend(pdfs(&path));
        } else if path.extension().is_some_and(|e| e == "pdf") {
            out.push(path);
        }
    }
    out.sort();
    out
}

/// Runs `campaign` into a fresh folder named `name`; the folder.
fn run(campaign: &str, name: &str) -> PathBuf {
    run_with(campaign, name, &[])
}

/// [`run`] with more options (`--lang zh`).
fn run_with(campaign: &str, name: &str, extra: &[&str]) -> PathBuf {
    let out = std::env::temp_dir().join(format!("axcheck-layout-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let mut args = vec!["run", campaign, "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&args);
    assert!(code == 0 || code == 1, "{code}: {stdout}{stderr}");
    out
}

/// Every PDF of `out` checked; the report names each problem with its file.
fn assert_no_overprinting(out: &Path, reports: usize) {
    let files = pdfs(out);
    assert_eq!(files.len(), reports, "{files:?}");
    let mut all = Vec::new();
    for pdf in &files {
        let pages = pages(pdf);
        assert!(!pages.is_empty() && pages.iter().all(|p| !p.words.is_empty()));
        let shown = pdf.strip_prefix(out).unwrap().display().to_string();
        all.extend(
            problems(&pages)
                .into_iter()
                .map(|p| format!("{shown}: {p}")),
        );
    }
    assert!(
        all.is_empty(),
        "{} problems:\n{}",
        all.len(),
        all[..all.len().min(40)].join("\n")
    );
}

#[test]
fn the_checker_sees_what_a_reader_sees() {
    let word = |x0: f64, y0: f64, x1: f64, y1: f64, text: &str| Word {
        x0,
        y0,
        x1,
        y1,
        text: text.into(),
    };
    let page = |words: Vec<Word>| Page {
        width: 595.276,
        height: 841.89,
        words,
    };
    // The example's VMC-07 X page 1 as it was: the B̄ row over the footer's title.
    let footer_line = [
        word(45.35, 806.47, 72.86, 814.94, "VMC-07"),
        word(476.0, 806.47, 492.74, 814.94, "Page"),
    ];
    let clash = page(vec![
        word(45.35, 802.25, 51.04, 812.66, "B̄"),
        footer_line[0].clone(),
        footer_line[1].clone(),
    ]);
    let found = problems(&[clash]);
    assert!(found.iter().any(|p| p.contains("overprints")), "{found:?}");
    assert!(
        found.iter().any(|p| p.contains("runs into the footer")),
        "{found:?}"
    );
    // The footer alone, and lines set close without touching (a number over its label).
    let fine = page(vec![
        footer_line[0].clone(),
        footer_line[1].clone(),
        word(73.99, 136.83, 94.14, 158.62, "21"),
        word(71.44, 156.64, 96.70, 166.32, "TESTS"),
    ]);
    assert_eq!(problems(&[fine]), Vec::<String>::new());
    // Off the page, and a footer title running into the page number.
    let off = page(vec![word(500.0, 100.0, 640.0, 110.4, "Fräszentrum")]);
    assert!(problems(&[off])[0].contains("leaves the page"));
    let into_number = page(vec![
        word(300.0, 806.47, 480.0, 814.94, "Halle3-Platz4"),
        footer_line[1].clone(),
    ]);
    assert!(problems(&[into_number])[0].contains("overprints"));
}

#[test]
fn no_report_of_the_example_campaign_overprints() {
    let out = run("example-campaign/campaign.yaml", "example");
    // 33 tests (27 positioning tests, MILL-8's 6 others) and the summary.
    assert_no_overprinting(&out, 34);
    // The page that had the B̄ row over its footer.
    let page = &pages(&out.join("reports/VMC-07/X.pdf"))[0];
    let band = page.height - FOOTER_BAND;
    let in_footer = footer(page);
    let body_bottom = (page.words.iter().zip(&in_footer))
        .filter(|(_, f)| !**f)
        .map(|(w, _)| w.y1)
        .fold(0.0, f64::max);
    assert!(body_bottom <= band, "{body_bottom} > {band}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn no_report_of_the_names_campaign_overprints() {
    let out = run("tests/data/names/campaign.yaml", "names");
    assert_no_overprinting(&out, 9);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn no_report_of_a_certificate_overprints() {
    let out = run("tests/data/certificate/campaign.yaml", "certificate-layout");
    // MILL-3 X's positioning and straightness, MILL-8 Y, and the summary.
    assert_no_overprinting(&out, 4);
    let _ = std::fs::remove_dir_all(&out);
}

/// The same in Chinese and Russian (README "Report languages"): longer words (GOST 27843's
/// terms), ideographs, a decimal comma.
#[test]
fn no_report_in_chinese_or_russian_overprints() {
    for lang in ["zh", "ru"] {
        let name = format!("names-{lang}");
        let out = run_with("tests/data/names/campaign.yaml", &name, &["--lang", lang]);
        assert_no_overprinting(&out, 9);
        let _ = std::fs::remove_dir_all(&out);
        let out = run_with(
            "example-campaign/campaign.yaml",
            &format!("example-{lang}"),
            &["--lang", lang],
        );
        assert_no_overprinting(&out, pdfs(&out).len().max(1));
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// The text of the first page of `pdf`, without whitespace (pdftotext breaks lines).
fn first_page_text(pdf: &Path) -> String {
    let out = std::process::Command::new("pdftotext")
        .args(["-f", "1", "-l", "1"])
        .arg(pdf)
        .arg("-")
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout)
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect()
}

/// Every page's text as pdftotext reads it, words joined by single spaces.
fn words_of(pdf: &Path) -> String {
    let out = std::process::Command::new("pdftotext")
        .arg(pdf)
        .arg("-")
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The words of every page's body, joined (a page's footer would fall inside a name that
/// runs on).
fn body_text(pdf: &Path) -> String {
    (pages(pdf).iter())
        .flat_map(|page| {
            (page.words.iter().zip(footer(page)))
                .filter(|(_, f)| !f)
                .map(|(w, _)| w.text.clone())
        })
        .collect()
}

#[test]
fn long_names_are_shortened_and_printed_whole_once() {
    let out = run("tests/data/names/campaign.yaml", "long-names");
    let long: String = "Fräszentrum-Baureihe-"
        .repeat(600)
        .chars()
        .take(10_000)
        .collect();
    let dir = out
        .join("reports")
        .join(&long[..long.char_indices().nth(64).unwrap().0]);
    let report = dir.join("X.pdf");
    assert!(
        report.is_file(),
        "{:?}",
        std::fs::read_dir(out.join("reports"))
    );
    // Whole once, under the facts, starting on the first page; elsewhere shortened with an
    // ellipsis (in the facts' column it filled nine pages). Compared without hyphens and
    // whitespace: pdftotext drops a hyphen that ends a line.
    let plain = |s: &str| -> String {
        s.chars()
            .filter(|c| *c != '-' && !c.is_whitespace())
            .collect()
    };
    let all = plain(&body_text(&report));
    assert_eq!(all.matches(&plain(&long)).count(), 1);
    assert!(pages(&report).len() <= 8, "{} pages", pages(&report).len());
    let first = plain(&first_page_text(&report));
    assert!(first.contains("Machine,infull"), "{first:.600}");
    let start: String = long.chars().take(300).collect();
    assert!(first.contains(&plain(&start)), "{first:.600}");
    let short = format!("{}…", long.chars().take(59).collect::<String>());
    assert!(first.contains(&plain(&short)), "{first:.400}");
    // The footer's title on one line, ended by an ellipsis before the page number.
    let pages = pages(
        &out.join("reports/DMC80H-duoBLOCK-Halle3-Platz4/X-Achse-Hauptspindel-Linearmaßstab.pdf"),
    );
    for (p, page) in pages.iter().enumerate() {
        let in_footer = footer(page);
        let number = page.words.iter().rfind(|w| w.text == "Page").unwrap();
        let title: Vec<&Word> = (page.words.iter().zip(&in_footer))
            .filter(|(w, f)| **f && (w.y1 - number.y1).abs() < 0.5 && w.x1 <= number.x0)
            .map(|(w, _)| w)
            .collect();
        let last = title.last().unwrap();
        assert!(last.text.ends_with('…'), "page {}: {title:?}", p + 1);
        assert!(last.x1 < number.x0 - 6.0);
        // One line: no other footer line but the closing note's on the last page.
        let lines = (page.words.iter().zip(&in_footer))
            .filter(|(w, f)| **f && w.y1 > number.y1 + 0.5)
            .count();
        assert_eq!(lines, 0, "page {}", p + 1);
    }
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn file_names_keep_the_letters_of_every_script() {
    let out = run("tests/data/names/campaign.yaml", "file-names");
    for path in [
        "reports/Станок-16К20Ф3-цех-механической-обработки/Ось_X.pdf",
        "reports/Станок-16К20Ф3-цех-механической-обработки/Поворотная_ось_A.pdf",
        "reports/立式加工中心-三号车间-精密加工/主轴Z轴.pdf",
        "reports/מכונת-כרסום-אנכית/ציר_Y.pdf",
        "reports/آلة-تفريز-عمودية/المحور_X.pdf",
        "reports/DMC80H-duoBLOCK-Halle3-Platz4/X-Achse-Hauptspindel-Linearmaßstab.pdf",
    ] {
        assert!(out.join(path).is_file(), "{path}: {:?}", pdfs(&out));
    }
    // results.json names the compensation table by the same rule.
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let rotary = (results["axes"].as_array().unwrap().iter())
        .find(|a| a["axis"] == "Поворотная ось A")
        .unwrap();
    let table = "compensation/Станок-16К20Ф3-цех-механической-обработки/Поворотная_ось_A.txt";
    assert_eq!(rotary["compensation"]["file"], table);
    assert!(out.join(table).is_file());
    // The run's list of its outputs names the same files.
    let manifest = std::fs::read_to_string(out.join(".axcheck-outputs")).unwrap();
    assert!(manifest.contains("Ось_X.pdf"), "{manifest}");
    assert!(!manifest.contains("____X"), "{manifest}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn reports_speak_in_micrometres_and_words() {
    let out = run("example-campaign/campaign.yaml", "words");
    for pdf in pdfs(&out) {
        let text = String::from_utf8_lossy(
            &std::process::Command::new("pdftotext")
                .arg(&pdf)
                .arg("-")
                .output()
                .unwrap()
                .stdout,
        )
        .into_owned();
        let shown = pdf.strip_prefix(&out).unwrap().display().to_string();
        for word in text.split(|c: char| c.is_whitespace() || ",;:()".contains(c)) {
            assert_ne!(word, "um", "{shown}: a budget's unit as um");
            // `made_worse`, `slope_um_per_m`: lower-case words joined by underscores (but
            // `time_s`, the name of a column of the file, is what the file must have).
            let key = word.split('_').count() > 1
                && word != "time_s"
                && word
                    .split('_')
                    .all(|w| !w.is_empty() && w.chars().all(|c| c.is_ascii_lowercase()));
            assert!(!key, "{shown}: internal key {word:?}");
        }
    }
    let mill = first_page_text(&out.join("reports/MILL-3/Y.pdf"));
    let all = words_of(&out.join("reports/MILL-3/Y.pdf"));
    assert!(
        all.contains("found it made worse (sign inverted)"),
        "{mill:.300}"
    );
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn the_decision_chart_rounds_as_the_results_table() {
    let out = run("example-campaign/campaign.yaml", "decision");
    let text = words_of(&out.join("reports/ROTARY-T/A.pdf"));
    // The table: A = 8.35 ± 2.33 against 10.00; the chart's row of A prints the same
    // digits and the zone from them, 10.00 ∓ 2.33 (it printed "A 8.3 7.7 … 12.3").
    assert!(text.contains("8.35 ±2.33"), "{text:.3000}");
    assert!(text.contains("A 8.35 7.67 … 12.33"), "{text}");
    let _ = std::fs::remove_dir_all(&out);
}

/// Every glyph drawn on the pages of `pdf`: its font's name without the subset tag
/// (`Inter-Bold-Identity-H`) and its CID. Typst writes every face as a CID font with
/// two-byte codes, and glyph 0 is `.notdef`: the empty box of a letter no face has.
fn glyphs_drawn(pdf: &Path) -> Vec<(String, u16)> {
    use lopdf::Object;
    let doc = lopdf::Document::load(pdf).unwrap();
    let mut glyphs = Vec::new();
    for page in doc.get_pages().into_values() {
        let fonts = doc.get_page_fonts(page).unwrap();
        let content = lopdf::content::Content::decode(&doc.get_page_content(page)).unwrap();
        let mut font = String::new();
        for op in &content.operations {
            let strings: Vec<&[u8]> = match (op.operator.as_str(), op.operands.first()) {
                ("Tf", Some(name)) => {
                    let dict = fonts[name.as_name().unwrap()];
                    let base = dict.get(b"BaseFont").unwrap().as_name().unwrap();
                    let base = String::from_utf8_lossy(base);
                    font = base.split_once('+').map_or(&*base, |(_, f)| f).to_string();
                    continue;
                }
                ("Tj", Some(Object::String(s, _))) => vec![s],
                ("TJ", Some(Object::Array(parts))) => {
                    (parts.iter()).filter_map(|p| p.as_str().ok()).collect()
                }
                _ => continue,
            };
            for s in strings {
                assert_eq!(s.len() % 2, 0, "{font}: two-byte codes");
                (s.chunks(2))
                    .for_each(|c| glyphs.push((font.clone(), u16::from_be_bytes([c[0], c[1]]))));
            }
        }
    }
    glyphs
}

/// The text of the first page of `pdf` as pdftotext reads it, without whitespace and the
/// direction marks it puts around right-to-left words.
fn first_page_letters(pdf: &Path) -> String {
    (first_page_text(pdf).chars())
        .filter(|c| !matches!(c, '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}'))
        .collect()
}

/// Hebrew, Arabic and CJK names print with real glyphs: each in an embedded face of its
/// script (not a serif or a monospace face Typst found for the letters Inter lacks), no
/// `.notdef` anywhere, and pdftotext reads every name back. Right to left too: pdftotext
/// turns the glyphs of an RTL word, which stand right to left, back into the word, and
/// reads a line of RTL words in their order; the parts of a name joined by hyphens in a
/// left-to-right line it gives as they stand, right to left (glyphs drawn in the order of
/// the text would read as each word backwards).
#[test]
fn names_in_every_script_print_with_real_glyphs() {
    let out = run("tests/data/names/campaign.yaml", "glyphs");
    let files = pdfs(&out);
    assert_eq!(files.len(), 9);
    let faces = [
        "Inter-",
        "NotoSansHebrew-",
        "NotoSansArabic-",
        "DroidSansFallback",
        "DejaVuSansMono",
    ];
    for pdf in &files {
        let shown = pdf.strip_prefix(&out).unwrap().display().to_string();
        let glyphs = glyphs_drawn(pdf);
        assert!(glyphs.len() > 500, "{shown}: {} glyphs", glyphs.len());
        let notdef: Vec<&String> = glyphs.iter().filter(|g| g.1 == 0).map(|g| &g.0).collect();
        assert!(
            notdef.is_empty(),
            "{shown}: {} .notdef glyphs in {notdef:?}",
            notdef.len()
        );
        for (font, _) in &glyphs {
            assert!(
                faces.iter().any(|f| font.starts_with(f)),
                "{shown}: a glyph in {font}"
            );
        }
    }
    // Name as written → as pdftotext reads the report's first page.
    let reports = [
        (
            "立式加工中心-三号车间-精密加工/主轴Z轴.pdf",
            "DroidSansFallback",
            &[
                (
                    "立式加工中心-三号车间-精密加工",
                    "立式加工中心-三号车间-精密加工",
                ),
                ("立式加工中心 VMC-850", "立式加工中心VMC-850"),
                ("三号车间", "三号车间"),
                ("主轴Z轴", "主轴Z轴"),
            ],
        ),
        (
            "מכונת-כרסום-אנכית/ציר_Y.pdf",
            "NotoSansHebrew-",
            &[
                ("מכונת-כרסום-אנכית", "אנכית-כרסום-מכונת"),
                ("מרכז עיבוד אנכי", "מרכזעיבודאנכי"),
                ("אולם 2", "2אולם"),
                ("ציר Y", "צירY"),
            ],
        ),
        (
            "آلة-تفريز-عمودية/المحور_X.pdf",
            "NotoSansArabic-",
            &[
                ("آلة-تفريز-عمودية", "عمودية-تفريز-آلة"),
                ("مركز تشغيل عمودي", "مركزتشغيلعمودي"),
                ("القاعة 3", "3القاعة"),
                ("المحور X", "المحورX"),
            ],
        ),
    ];
    for (file, face, names) in reports {
        let pdf = out.join("reports").join(file);
        let text = first_page_letters(&pdf);
        for (name, read) in names.iter() {
            assert!(
                text.contains(read),
                "{file}: {name} not read as {read}: {text:.400}"
            );
        }
        let drawn = glyphs_drawn(&pdf);
        assert!(
            drawn.iter().any(|(f, _)| f.starts_with(face)),
            "{file}: nothing in {face}"
        );
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// The names campaign with three inspections in a history (2024 to 2026; its longest
/// machine given a limit its X exceeds, so that it is flagged): the reports of the last run
/// (each with its history section, the summary with the flagged series) and `trend`'s
/// trends.pdf neither overprint nor leave the page, and trends.pdf prints each long name
/// whole once (its headings shortened).
#[test]
fn no_report_of_a_history_with_long_names_overprints() {
    let dir = crate::common::scratch("layout-trends");
    let campaign = dir.join("names");
    crate::common::copy_tree(Path::new("tests/data/names"), &campaign);
    let yaml = std::fs::read_to_string(campaign.join("campaign.yaml")).unwrap();
    let gantry = "data: data/gantry1-x-full.csv}";
    assert!(yaml.contains(gantry));
    let yaml = yaml.replace(
        gantry,
        "data: data/gantry1-x-full.csv, tolerances: {E: 10}}",
    );
    let (history, out) = (dir.join("history"), dir.join("out"));
    let s = |p: &Path| p.to_str().unwrap().to_string();
    for date in ["2024-11-20", "2025-11-20", "2026-11-20"] {
        let dated = yaml.replace("date: 2026-11-20", &format!("date: {date}"));
        std::fs::write(campaign.join("campaign.yaml"), dated).unwrap();
        let pdf = if date == "2026-11-20" {
            "--jobs=2"
        } else {
            "--no-pdf"
        };
        let args = [
            "run",
            &s(&campaign.join("campaign.yaml")),
            "--out",
            &s(&out),
            pdf,
            "--history",
            &s(&history),
        ];
        let (code, stdout, stderr) = axcheck(&args);
        assert!(code <= 1, "{date}: {code}: {stdout}{stderr}");
    }
    let summary = words_of(&out.join("summary.pdf"));
    assert!(
        summary.contains("Trends over the inspection history (2024-11-20 to 2026-11-20)"),
        "{summary:.2000}"
    );
    assert_no_overprinting(&out, 9);
    let trends = dir.join("trends");
    let (code, stdout, stderr) = axcheck(&["trend", &s(&history), "--out", &s(&trends)]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let pdf = trends.join("trends.pdf");
    assert_no_overprinting(&trends, 1);
    // The long machine first (flagged), under its shortened name, and whole once.
    let plain = |s: &str| -> String {
        s.chars()
            .filter(|c| *c != '-' && !c.is_whitespace())
            .collect()
    };
    let long: String = "Fräszentrum-Baureihe-"
        .repeat(600)
        .chars()
        .take(10_000)
        .collect();
    assert!(
        stdout.contains(&format!("\n  {long} X E: over its limit")),
        "{stdout:.300}"
    );
    let text = plain(&body_text(&pdf));
    assert_eq!(text.matches(&plain(&long)).count(), 1);
    assert!(text.contains("Machine,infull"), "{text:.600}");
    assert!(glyphs_drawn(&pdf).iter().all(|g| g.1 != 0));
    let _ = std::fs::remove_dir_all(&dir);
}
