//! errplot without any adapter still writes every CPU-side result and says which columns need
//! an adapter and how to get one. (Its own binary: it sets the child's environment only.)

mod common;

use std::path::Path;
use std::process::Command;

#[test]
fn errplot_without_adapter_writes_cpu_results_and_names_the_fix() {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("errplot-no-adapter");
    let _ = std::fs::remove_dir_all(&out);
    let run = Command::new(env!("CARGO_BIN_EXE_errplot"))
        .args(["--quick", "--out"])
        .arg(&out)
        .env("PREPASS_ADAPTER", "no adapter has this name 7f3a")
        .output()
        .expect("errplot runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "errplot failed: {stderr}");

    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("- Adapter: **none**"), "{report}");
    assert!(
        report.contains("mesa-vulkan-drivers"),
        "the fix is named: {report}"
    );
    assert!(
        report.contains("needs adapter"),
        "adapter-only cells are marked"
    );

    // The CPU-side plots exist as SVG and as real PNGs.
    for stem in ["depth_resolution", "linear_depth_error"] {
        let svg = std::fs::read_to_string(out.join(format!("{stem}.svg"))).unwrap();
        assert!(
            svg.contains("<svg") && svg.contains("log scale"),
            "{stem}.svg"
        );
        let png = std::fs::read(out.join(format!("{stem}.png"))).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{stem}.png");
    }

    // Cost rows: SPIR-V counts for every variant, CPU ns/call for each twin, no GPU time.
    let csv = std::fs::read_to_string(out.join("error_vs_cost.csv")).unwrap();
    let header = split_csv(csv.lines().next().unwrap());
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let rows: Vec<Vec<String>> = csv.lines().skip(1).map(split_csv).collect();
    assert!(rows.iter().all(|r| r.len() == header.len()), "{csv}");
    assert!(rows.len() >= 5, "{csv}");
    for r in &rows {
        assert!(
            r[col("spirv_instructions")].parse::<u32>().unwrap() > 0,
            "{r:?}"
        );
        assert_eq!(r[col("gpu_ns_per_eval")], "", "{r:?}");
    }
    let twin = rows
        .iter()
        .find(|r| r[col("variant")] == "hyperbolic_depth_from_depth24")
        .unwrap();
    assert!(
        twin[col("cpu_ns_per_call")].parse::<f64>().is_ok(),
        "{twin:?}"
    );
    // Its error comes from the twin's exhaustive CPU sweep: correctly rounded, so at most half
    // an ULP (src/depth24.rs derives why), and the sweep did run (a value, not an empty cell).
    let max: f64 = twin[col("max_error")].parse().unwrap();
    assert!((0.25..=0.5).contains(&max), "{twin:?}");
}

/// Split one CSV line, honouring RFC 4180 quotes.
fn split_csv(line: &str) -> Vec<String> {
    let (mut fields, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => fields.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    fields.push(cur);
    fields
}
