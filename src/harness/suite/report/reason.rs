//! The kind of a checker's explanation ([`reason_of`]): its first line with numbers and
//! bracketed groups written as placeholders, so that failures of one kind share it.

/// The kind of a checker's explanation: the first line of `message` with each number
/// (a run of digits, `/`, `.` not inside a word, with its sign) written `N` and each
/// bracketed group written `(..)` or `[..]`, so that explanations that differ only in
/// coordinates, pixels and counts share it.
///
/// ```
/// use rasterproof::harness::suite::report::reason_of;
/// assert_eq!(
///     reason_of("pixel (29, 1) is covered 2 times, by [5, 6]; 15 such pixels\n  triangle 5: ..."),
///     "pixel (..) is covered N times, by [..]; N such pixels"
/// );
/// assert_eq!(
///     reason_of("vertex 9 (1/2, 41/2) is outside window edge 3: a x + b y + c = -39/2097152"),
///     "vertex N (..) is outside window edge N: a x + b y + c = N"
/// );
/// assert_eq!(reason_of("float32-naive [5] f32"), "float32-naive [..] f32");
/// ```
pub fn reason_of(message: &str) -> String {
    let line = message.lines().next().unwrap_or("");
    let chars: Vec<char> = line.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let after_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if let Some(close) = closing(c) {
            let end = matching(&chars, i, c, close);
            out.push(c);
            out.push_str("..");
            out.push(close);
            i = end + 1;
        } else if !after_word && starts_number(&chars, i) {
            out.push('N');
            let start = i;
            i += 1;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '/' || chars[i] == '.') {
                i += 1;
            }
            // A trailing `.` or `/` ends the sentence, not the number.
            while i > start + 1 && matches!(chars[i - 1], '.' | '/') {
                i -= 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// The closing bracket of `c`, if it opens a group.
fn closing(c: char) -> Option<char> {
    match c {
        '(' => Some(')'),
        '[' => Some(']'),
        _ => None,
    }
}

/// The index of the bracket closing the one at `open`, nested groups counted; the last
/// index when it is never closed.
fn matching(chars: &[char], open: usize, c: char, close: char) -> usize {
    let mut depth = 0u32;
    for (j, &d) in chars.iter().enumerate().skip(open) {
        if d == c {
            depth += 1;
        } else if d == close {
            depth -= 1;
            if depth == 0 {
                return j;
            }
        }
    }
    chars.len() - 1
}

/// Whether a number starts at `i`: a digit, or a `-` before one.
fn starts_number(chars: &[char], i: usize) -> bool {
    chars[i].is_ascii_digit() || (chars[i] == '-' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
}

#[cfg(test)]
mod tests {
    use super::reason_of;

    #[test]
    fn reasons_keep_words_and_drop_numbers_and_groups() {
        assert_eq!(
            reason_of("[1, 2] -> [3, 4]: endpoints not included: first [1, 2], last [3, 5]"),
            "[..] -> [..]: endpoints not included: first [..], last [..]"
        );
        assert_eq!(
            reason_of("21 differing pixels; first (3, 4): exact-plain [], float32-naive [5, 6]"),
            "N differing pixels; first (..): exact-plain [..], float32-naive [..]"
        );
        assert_eq!(reason_of("a 2^-16 grid, 1.5 px. Then 3."), "a N^N grid, N px. Then N.");
        assert_eq!(reason_of("unclosed (1, [2"), "unclosed (..)");
        assert_eq!(reason_of(""), "");
    }
}
