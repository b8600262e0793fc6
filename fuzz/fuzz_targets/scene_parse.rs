//! Arbitrary bytes into the scene parser: it must answer `Ok` or `Err`, never panic, and a
//! scene it accepts must survive `to_json` and a second parse unchanged. The fast reader
//! (compact numbers, one streaming pass) must give what the slow one (a tree, big
//! rationals) gives, scene or error, on one thread and on two, and `Compact::parse` what
//! `parse_rational` reads.
//! (Its first find: a 256-character limit on number text refused what `to_json` wrote for
//! `1e300`; now the parser bounds values by bits, see `rasterproof::num::exact::MAX_BITS`,
//! and the case is the unit test `scene::parse::tests::fuzz_case_01_huge_exponent_round_trip`.)

#![no_main]

use libfuzzer_sys::fuzz_target;
use rasterproof::num::compact::Compact;
use rasterproof::num::parse_rational;
use rasterproof::scene::parse::parse_scene_slow;
use rasterproof::scene::{parse_scene, parse_scene_with, ParseOptions};

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let fast = parse_scene(text, "<fuzz>").map_err(|e| e.to_string());
        let slow = parse_scene_slow(text, "<fuzz>").map_err(|e| e.to_string());
        assert_eq!(fast, slow, "the fast and slow readers differ on:\n{text}");
        let parallel = parse_scene_with(text.as_bytes(), "<fuzz>", &ParseOptions::with_jobs(2)).map_err(|e| e.to_string());
        assert_eq!(parallel, slow, "the reader on two threads differs on:\n{text}");
        for word in text.split(|c: char| c.is_whitespace() || c == ',' || c == '[' || c == ']') {
            let compact = Compact::parse(word);
            assert_eq!(compact.clone().map(|c| c.to_big()), parse_rational(word), "{word:?}");
            if let Ok(c) = compact {
                assert_eq!(Compact::from_big(c.to_big()), c, "{word:?}: one form per value");
            }
        }
    }
    let Ok(scene) = parse_scene_with(data, "<fuzz>", &ParseOptions::default()) else {
        return;
    };
    let text = scene.to_json();
    match parse_scene(&text, "<round-trip>") {
        Ok(again) => assert_eq!(again, scene, "round trip changed the scene:\n{text}"),
        Err(e) => panic!("to_json wrote a scene the parser refuses: {e}\n{text}"),
    }
});
