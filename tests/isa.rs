//! prepass::isa: every shipped function compiled by ACO and brw on every target.

use prepass::isa::{Costing, Function, Target};

#[test]
fn probe() {
    let report = Costing::new()
        .disassembly(true)
        .cost(&[
            Function::new(prepass::wgsl::NORMAL_OCT, "encode_normal_oct24"),
            Function::new(prepass::wgsl::NORMAL_OCT, "encode_normal_oct24_fast"),
        ])
        .unwrap();
    for t in &report.targets {
        match &t.outcome {
            Ok(c) => {
                println!("{} {} {}", t.target, c.driver, c.driver_info);
                for f in &c.functions {
                    match f {
                        Ok(cost) => println!("  {:?}\n  raw {:?}", cost.net, cost.kernel.raw),
                        Err(e) => println!("  error {e}"),
                    }
                }
            }
            Err(e) => println!("{}: not measured: {e}", t.target),
        }
    }
    let _ = Target::ALL;
}
