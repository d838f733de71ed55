//! Every figure of a quick errplot run is checked as it is written (errplot fails on a figure
//! with text or a box outside the image, two series drawn alike or named alike, or no data),
//! and `errplot --check` measures the written SVGs again and catches text that runs off. With
//! `PREPASS_WRITE_DOCS=1` the run's `which_to_pick.png` becomes the README's figure.

use std::path::Path;
use std::process::Command;

fn errplot(args: &[&str], dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_errplot"))
        .args(args)
        .arg(dir)
        .output()
        .expect("errplot runs")
}

#[test]
fn every_figure_of_a_quick_run_fits_its_image() {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("errplot-figures");
    let _ = std::fs::remove_dir_all(&out);
    let run = errplot(&["--quick", "--out"], &out);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "errplot --quick failed: {stderr}");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(
        !report.contains("- Adapter: **none**"),
        "no adapter: the figures of the error sections need one ({stderr})"
    );

    // Every figure the report embeds exists as PNG and SVG; the ones issue 61 redrew among them.
    let figures: Vec<&str> = report
        .split("](")
        .skip(1)
        .filter_map(|s| s.split(')').next())
        .filter(|s| s.ends_with(".png"))
        .collect();
    for stem in [
        "pareto_normal_encoding__encode_navi21",
        "pareto_normal_encoding__decode_dg2",
        "normal_error_histogram",
        "which_to_pick",
    ] {
        assert!(figures.contains(&format!("{stem}.png").as_str()), "{stem}");
    }
    for png in &figures {
        let bytes = std::fs::read(out.join(png)).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{png}");
        assert!(out.join(png.replace(".png", ".svg")).exists(), "{png}");
    }

    // The README's "which to pick" figure is this run's (PREPASS_WRITE_DOCS=1 writes it, as
    // `bash .ci/docs` does the README's tables).
    let readme_figure = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/which_to_pick.png");
    if std::env::var_os("PREPASS_WRITE_DOCS").is_some() {
        std::fs::copy(out.join("which_to_pick.png"), &readme_figure).unwrap();
    }
    let committed = std::fs::read(&readme_figure).expect("docs/which_to_pick.png");
    assert_eq!(&committed[..8], b"\x89PNG\r\n\x1a\n");

    // The figure tags the README's recommendations: each use's encodings, as its list names them.
    let svg = std::fs::read_to_string(out.join("which_to_pick.svg")).unwrap();
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    for (bullet, named, tag) in [
        ("- **Thin G-buffer:**", "oct16", "oct16: thin G-buffer"),
        (
            "- **Thin G-buffer:**",
            "oct24 `_fast`",
            "oct24 fast: thin G-buffer",
        ),
        ("- **Quality:**", "oct24", "oct24: quality"),
        ("- **Quality:**", "oct32", "oct32: quality"),
    ] {
        let line = readme
            .lines()
            .find(|l| l.starts_with(bullet))
            .unwrap_or_else(|| panic!("README has no {bullet:?} line"));
        assert!(
            line.contains(named),
            "README's {bullet:?} no longer names {named}: {line}"
        );
        assert!(svg.contains(tag), "which_to_pick.svg does not tag {tag:?}");
    }

    let check = errplot(&["--check"], &out);
    let said = String::from_utf8_lossy(&check.stdout);
    assert!(check.status.success(), "{said}");
    assert!(
        said.contains(&format!("{} SVG files, 0 problems", figures.len())),
        "{said}"
    );
}

/// The check is not vacuous: a title pushed past the left edge is reported, by file and text.
#[test]
fn the_check_reports_text_outside_the_image() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("errplot-figures-clipped");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let svg = |x: i32| {
        format!(
            "<svg width=\"300\" height=\"100\" viewBox=\"0 0 300 100\" xmlns=\"http://www.w3.org/2000/svg\">\n\
             <text x=\"{x}\" y=\"10\" dy=\"0.76em\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"16\">\n\
             Max error against cost\n</text>\n</svg>\n"
        )
    };
    std::fs::write(dir.join("fits.svg"), svg(150)).unwrap();
    let fine = errplot(&["--check"], &dir);
    assert!(
        fine.status.success(),
        "{}",
        String::from_utf8_lossy(&fine.stdout)
    );
    std::fs::write(dir.join("clipped.svg"), svg(40)).unwrap();
    let run = errplot(&["--check"], &dir);
    let said = String::from_utf8_lossy(&run.stdout);
    assert!(!run.status.success(), "{said}");
    assert!(
        said.contains("clipped.svg: text \"Max error against cost\""),
        "{said}"
    );
    assert!(said.contains("2 SVG files, 1 problems"), "{said}");
}
