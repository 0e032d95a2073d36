//! Parsed request texts kept by their text, so that a stream of requests on the same
//! integrand and range parses each text once.
//!
//! The integrand's parse was about 17 000 instructions, half of `eval`'s own cost of a
//! small integral's request, and the two ends' about 4 600 more
//! (docs/quadrature.md, "`eval`'s own cost per request"). A cache holds at most its capacity of
//! entries and replaces the oldest when full; a stream of distinct texts parses each,
//! as without it. A text that does not parse is not kept (its error is computed again).

use std::cell::RefCell;
use std::rc::Rc;

use maugis::quad::expr::{End, Expr};
use maugis::Result;

/// Integrands kept ([`parsed_expr`]).
const EXPR_CACHE_SIZE: usize = 64;

/// Ends of ranges kept ([`parsed_end`]).
const END_CACHE_SIZE: usize = 16;

/// At most `cap` values, each under the text it was parsed from.
struct TextCache<T> {
    entries: Vec<(Box<str>, Rc<T>)>,
    /// The entry to replace next once full (the oldest).
    next: usize,
    cap: usize,
}

impl<T> TextCache<T> {
    const fn new(cap: usize) -> Self {
        TextCache { entries: Vec::new(), next: 0, cap }
    }

    /// The value of `text`, from the cache, or `parse(text)` kept for next time.
    fn get_or_parse(&mut self, text: &str, parse: impl FnOnce(&str) -> Result<T>) -> Result<Rc<T>> {
        if let Some((_, v)) = self.entries.iter().find(|(k, _)| **k == *text) {
            return Ok(v.clone());
        }
        let v = Rc::new(parse(text)?);
        let entry = (Box::from(text), v.clone());
        if self.entries.len() < self.cap {
            self.entries.push(entry);
        } else {
            self.entries[self.next] = entry;
            self.next = (self.next + 1) % self.cap;
        }
        Ok(v)
    }
}

thread_local! {
    static EXPRS: RefCell<TextCache<Expr>> = const { RefCell::new(TextCache::new(EXPR_CACHE_SIZE)) };
    static ENDS: RefCell<TextCache<End>> = const { RefCell::new(TextCache::new(END_CACHE_SIZE)) };
}

/// The integrand `text` parsed ([`Expr::parse`]), from the cache when it was seen before.
pub fn parsed_expr(text: &str) -> Result<Rc<Expr>> {
    EXPRS.with(|c| c.borrow_mut().get_or_parse(text, Expr::parse))
}

/// The end of a range `text` parsed ([`End::parse`]), from the cache when it was seen before.
pub fn parsed_end(text: &str) -> Result<Rc<End>> {
    ENDS.with(|c| c.borrow_mut().get_or_parse(text, End::parse))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A full cache replaces its oldest entry, and a value comes back under its own text.
    #[test]
    fn keeps_the_newest_and_answers_by_text() {
        let mut c = TextCache::new(2);
        let mut parses = 0;
        let mut get = |c: &mut TextCache<usize>, t: &str| {
            *c.get_or_parse(t, |t| {
                parses += 1;
                Ok(t.len())
            })
            .unwrap()
        };
        assert_eq!(get(&mut c, "a"), 1);
        assert_eq!(get(&mut c, "bb"), 2);
        assert_eq!(get(&mut c, "a"), 1);
        assert_eq!(get(&mut c, "ccc"), 3); // replaces "a", the oldest
        assert_eq!(get(&mut c, "bb"), 2);
        assert_eq!(get(&mut c, "a"), 1); // parsed again, replaces "bb"
        assert_eq!(get(&mut c, "ccc"), 3);
        assert_eq!(parses, 4);
        let err = c.get_or_parse("x", |_| Err(maugis::Error::NotADecimal { text: "x".into() }));
        assert!(err.is_err());
        assert_eq!(c.entries.len(), 2, "an error is not kept");
    }
}
