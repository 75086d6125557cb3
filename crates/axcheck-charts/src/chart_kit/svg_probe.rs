//! Test helpers that read a chart's SVG back: its texts, a text's tag, an attribute's values.
//! Shared by the chart modules' unit tests.

use crate::chart_kit::Style;

/// The text content of every `<text>` element.
pub(crate) fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let start = t.find('>')? + 1;
            let end = t.find("</text>")?;
            Some(t[start..end].trim().to_string())
        })
        .collect()
}

/// Whether a `<text>` element holds exactly `want`.
pub(crate) fn has_text(svg: &str, want: &str) -> bool {
    texts(svg).iter().any(|t| t == want)
}

/// The opening tag of the `<text>` element holding exactly `content`.
pub(crate) fn text_tag<'a>(svg: &'a str, content: &str) -> Option<&'a str> {
    svg.split("<text").skip(1).find_map(|t| {
        let start = t.find('>')?;
        let end = t.find("</text>")?;
        (t[start + 1..end].trim() == content).then_some(&t[..start])
    })
}

/// Every value of the attribute `attr` in the document, in order.
pub(crate) fn attr_values<'a>(svg: &'a str, attr: &str) -> Vec<&'a str> {
    let key = format!(" {attr}=\"");
    svg.match_indices(&key)
        .filter_map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            rest.find('"').map(|end| &rest[..end])
        })
        .collect()
}

/// One `<svg>` root, every `<text>` closed, no NaN or infinity written.
pub(crate) fn assert_well_formed(svg: &str) {
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<text").count(), svg.matches("</text>").count());
    assert_eq!(svg.matches("<svg").count(), 1);
    assert!(!svg.contains("NaN") && !svg.contains("inf\""));
}

/// Sizes a chart must survive: `usual`, nothing at all, small, and the largest there is.
pub(crate) fn degenerate_styles(usual: Style) -> [Style; 4] {
    let sized = |width_px, height_px| Style {
        width_px,
        height_px,
    };
    [
        usual,
        sized(0, 0),
        sized(300, 150),
        sized(u32::MAX, u32::MAX),
    ]
}
