//! Arbitrary bytes into the scene parser: it must answer `Ok` or `Err`, never panic, and a
//! scene it accepts must survive `to_json` and a second parse unchanged.
//! (Its first find: a 256-character limit on number text refused what `to_json` wrote for
//! `1e300`; now the parser bounds values by bits, see `rasterproof::num::exact::MAX_BITS`,
//! and the case is the unit test `scene::parse::tests::fuzz_case_01_huge_exponent_round_trip`.)

#![no_main]

use libfuzzer_sys::fuzz_target;
use rasterproof::scene::{parse_scene, parse_scene_bytes};

fuzz_target!(|data: &[u8]| {
    let Ok(scene) = parse_scene_bytes(data, "<fuzz>") else {
        return;
    };
    let text = scene.to_json();
    match parse_scene(&text, "<round-trip>") {
        Ok(again) => assert_eq!(again, scene, "round trip changed the scene:\n{text}"),
        Err(e) => panic!("to_json wrote a scene the parser refuses: {e}\n{text}"),
    }
});
