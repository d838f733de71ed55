//! With no usable adapter the harness fails with a message that names the fix.
//! (Its own binary: it changes the process environment.)

mod common;

#[test]
fn missing_adapter_error_names_the_fix() {
    // SAFETY: the only test in this binary, so no other thread reads the environment.
    unsafe { std::env::set_var("PREPASS_ADAPTER", "no adapter has this name 7f3a") };
    let e = prepass::harness::Gpu::new()
        .err()
        .expect("no adapter matches");
    let msg = e.to_string();
    assert!(msg.contains("mesa-vulkan-drivers"), "{msg}");
    assert!(msg.contains("PREPASS_ADAPTER"), "{msg}");
}
