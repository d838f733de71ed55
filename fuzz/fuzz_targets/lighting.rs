//! Fuzz every entry of `prepass_fuzz::LIGHTING` (the first input byte picks the entry).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| prepass_fuzz::dispatch(prepass_fuzz::LIGHTING, data));
