//! Reports in Chinese and Russian (`--lang`, `campaign.report.lang`, a machine's
//! `report.lang`): the parameters named with the standards' own terms beside their
//! symbols (GB/T 17421.2-2000 clause 2 in Chinese, GOST 27843-88 section 1 in Russian),
//! numbers and dates in the language's forms, read back from the PDFs with pdftotext.

use crate::common::{axcheck, data_path, scratch};
use std::path::{Path, PathBuf};

/// A campaign in a fresh folder: `campaign_extra` inside `campaign:`, machine M1 with the
/// ISO 230-2 worked example (Table 2) and `m1_extra`, machine M2 with the GOST 27843
/// example.
fn campaign(name: &str, campaign_extra: &str, m1_extra: &str) -> (PathBuf, PathBuf) {
    let dir = scratch(name);
    for f in ["iso230-2_table2.csv", "gost27843_example.csv"] {
        std::fs::copy(data_path(f), dir.join("data").join(f)).unwrap();
    }
    let yaml = format!(
        "campaign:\n  name: Languages\n  date: 2026-11-20\n  inspector: A. Metrologist\n{campaign_extra}\
         machines:\n  - id: M1\n{m1_extra}    axes:\n      - {{name: X, kind: linear, data: data/iso230-2_table2.csv, tolerances: {{A: 20, R: 8, B: 5}}}}\n\
         \x20 - id: M2\n    axes:\n      - {{name: Z, kind: linear, standard: gost27843, data: data/gost27843_example.csv, tolerances: {{A: 30}}}}\n"
    );
    let file = dir.join("campaign.yaml");
    std::fs::write(&file, yaml).unwrap();
    (dir, file)
}

/// `run FILE --out DIR/out --no-diagnose EXTRA…`; the output folder.
fn run(dir: &Path, file: &Path, extra: &[&str]) -> PathBuf {
    let out = dir.join("out");
    let mut args = vec![
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-diagnose",
    ];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&args);
    assert_eq!(code, 0, "{stdout}{stderr}");
    out
}

/// The text of `pdf` as `pdftotext -layout` gives it.
fn text(pdf: &Path) -> String {
    crate::common::pdftotext_layout(pdf)
}

/// The line of the results table that starts with `symbol`, with the term after it.
fn beside(text: &str, symbol: &str, term: &str) -> bool {
    text.lines().any(|l| {
        let l = l.trim_start();
        l.strip_prefix(symbol)
            .is_some_and(|rest| rest.starts_with(' ') && rest.trim_start().starts_with(term))
    })
}

#[test]
fn a_chinese_iso_report_names_the_parameters_in_the_terms_of_gbt_17421_2() {
    let (dir, file) = campaign("lang-zh", "", "");
    let out = run(&dir, &file, &["--lang", "zh"]);
    let zh = text(&out.join("reports/M1/X.pdf"));
    // GB/T 17421.2-2000, 2.23, 2.18 and 2.13, each beside its symbol.
    assert!(beside(&zh, "A", "轴线双向定位精度"), "{zh}");
    assert!(beside(&zh, "R", "轴线双向重复定位精度"), "{zh}");
    assert!(beside(&zh, "B", "轴线反向差值"), "{zh}");
    // (pdftotext doubles the combining macron's letter of B̄: the term alone.)
    assert!(zh.contains("轴线平均反向差值"), "{zh}");
    assert!(beside(&zh, "E", "轴线双向定位系统偏差"), "{zh}");
    for words in [
        "定位精度和重复定位精度检验报告",
        "检验结果",
        "合格",
        "检验日期",
        "2026-11-20",
        "第 1 页",
    ] {
        assert!(zh.contains(words), "{words} missing:\n{zh}");
    }
    // A decimal point in Chinese; the English headings gone.
    assert!(zh.contains("9.59"), "{zh}");
    for english in [
        "Results (values in",
        "Test-plan findings",
        "Page 1 of",
        "Measurement travel",
    ] {
        assert!(!zh.contains(english), "{english} left in:\n{zh}");
    }
    // The run's record names the option, so that `reproduce` writes Chinese again.
    let results = results(&out);
    assert_eq!(results["inputs"]["options"]["lang"], "zh");
    assert!(
        results["inputs"]["command"]
            .as_str()
            .unwrap()
            .ends_with("--lang zh")
    );
    // `reproduce` runs it again in Chinese: the same bytes.
    let (code, stdout, stderr) = axcheck(&["reproduce", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("byte for byte"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_russian_gost_report_names_the_parameters_in_the_terms_of_gost_27843() {
    let (dir, file) = campaign("lang-ru", "  report: {lang: ru}\n", "");
    let out = run(&dir, &file, &[]);
    let ru = text(&out.join("reports/M2/Z.pdf"));
    // GOST 27843-88, 1.14, 1.10 and 1.16, each beside its symbol.
    assert!(beside(&ru, "A", "точность позиционирования"), "{ru}");
    assert!(
        beside(&ru, "R↑", "повторяемость одностороннего позиционирования"),
        "{ru}"
    );
    assert!(
        beside(&ru, "B_max", "максимальная зона нечувствительности"),
        "{ru}"
    );
    assert!(ru.contains("зона нечувствительности") && ru.contains("повторяемость"));
    // A decimal comma, the date as DD.MM.YYYY, micrometres as мкм.
    assert!(ru.contains("18,00") && !ru.contains("18.00"), "{ru}");
    assert!(
        ru.contains("20.11.2026") && !ru.contains("2026-11-20"),
        "{ru}"
    );
    assert!(ru.contains("Результаты (значения в мкм)"), "{ru}");
    assert!(ru.contains("Страница 1 из"), "{ru}");
    // The summary too: its headings, the date, a decimal comma, micrometres as мкм.
    let summary = text(&out.join("summary.pdf"));
    for words in [
        "СВОДКА ПРОВЕРКИ ТОЧНОСТИ ПОЗИЦИОНИРОВАНИЯ",
        "Дата",
        "20.11.2026",
        "Оси (значения",
        "18,00",
        "мкм",
        "ГОДЕН",
    ] {
        assert!(summary.contains(words), "{words} missing:\n{summary}");
    }
    for english in ["Axes (values", "Page 1 of", "within tolerance", "Inputs"] {
        assert!(!summary.contains(english), "{english} left in:\n{summary}");
    }
    // summary.html: the page's language and its words for page.js.
    let html = std::fs::read_to_string(out.join("summary.html")).unwrap();
    assert!(html.contains("\"lang\":\"ru\"") && html.contains("\"html-search\":\"Поиск\""));
    // Without `--lang` nothing is recorded: the campaign says it.
    let results = results(&out);
    assert!(
        results["inputs"]["options"].get("lang").is_none(),
        "{results}"
    );
    assert_eq!(results["campaign"]["report"]["lang"], "ru");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `results.json` of `out`.
fn results(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap()
}

/// The first line of a report: its kind, in its language.
fn kind_line(pdf: &Path) -> String {
    text(pdf)
        .lines()
        .find(|l| !l.trim().is_empty())
        .unwrap()
        .trim()
        .to_string()
}

#[test]
fn the_command_line_overrides_the_machine_which_overrides_the_campaign() {
    let (dir, file) = campaign(
        "lang-precedence",
        "  report: {lang: zh}\n",
        "    report: {lang: ru}\n",
    );
    let out = run(&dir, &file, &[]);
    // M1 in its own Russian, M2 in the campaign's Chinese, the summary in Chinese.
    assert_eq!(
        kind_line(&out.join("reports/M1/X.pdf")),
        "ПРОТОКОЛ ПРОВЕРКИ ТОЧНОСТИ И ПОВТОРЯЕМОСТИ ПОЗИЦИОНИРОВАНИЯ"
    );
    assert_eq!(
        kind_line(&out.join("reports/M2/Z.pdf")),
        "定位精度和重复定位精度检验报告"
    );
    assert!(text(&out.join("summary.pdf")).contains("第 1 页"));
    // `--lang en` over both.
    let _ = std::fs::remove_dir_all(&out);
    let out = run(&dir, &file, &["--lang", "en"]);
    for pdf in ["reports/M1/X.pdf", "reports/M2/Z.pdf"] {
        assert_eq!(
            kind_line(&out.join(pdf)),
            "POSITIONING ACCURACY AND REPEATABILITY TEST REPORT"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_language_that_is_not_one_stops_at_its_line() {
    let (dir, file) = campaign("lang-bad", "  report: {lang: de}\n", "");
    let (code, stdout, stderr) = axcheck(&["check", file.to_str().unwrap()]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(
        stderr.contains("campaign.yaml:5:") && stderr.contains("expected en, zh or ru"),
        "{stderr}"
    );
    let (dir2, file2) = campaign("lang-bad-machine", "", "    report: {lang: fr}\n");
    // A broken machine fails alone, as an error test naming the line and the values.
    let (code, stdout, stderr) = axcheck(&["check", file2.to_str().unwrap()]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        stdout.contains("campaign.yaml:7:20: machines[0].report.lang")
            && stdout.contains("expected en, zh or ru"),
        "{stdout}"
    );
    let (code, _, stderr) = axcheck(&["run", file.to_str().unwrap(), "--lang", "de"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("en, zh or ru"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&dir2);
}
