//! Why an offset write (the offset pages, or an offsets document) is
//! refused: the document's shape, or a value the page does not take. The
//! message is the refusal's reason.

/// An offset write or offsets document the pages refuse.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub(super) enum OffsetError {
    /// The document is not a JSON object.
    #[error("the offsets document is a JSON object")]
    NotADocument,
    /// A page of the document is not an object.
    #[error("'{0}' must be an object")]
    PageNotObject(String),
    /// A value that must be a number (`what` names it: `[g55] x`).
    #[error("{0} must be a number")]
    NotANumber(String),
    /// A page key that is not an offset number.
    #[error("[{page}] key '{key}' is not an offset number")]
    BadKey { page: String, key: String },
    /// A page this machine does not have.
    #[error("unknown page '{0}' for this machine")]
    UnknownPage(String),
    /// A lathe tool entry that is not an object.
    #[error("[tool.{0}] must be an object")]
    ToolNotObject(usize),
    /// A lathe tool entry's field that is not a number.
    #[error("[tool.{n}] {key} must be a number")]
    ToolNotANumber { n: usize, key: String },
    /// A lathe tool entry's field that does not exist.
    #[error("[tool.{n}] {key}: unknown field")]
    ToolUnknownField { n: usize, key: String },
    /// A lathe tool entry's tip that is not a whole 0-9.
    #[error("[tool.{n}] tip {tip}: tip direction is 0-9")]
    ToolTip { n: usize, tip: f64 },
    /// An offset number past the table.
    #[error("offset number {n}: this machine has 1-{count}")]
    Number { n: usize, count: usize },
    /// A value past the page's range (`what`: geometry, wear, work offset).
    #[error("{what} {value}: the page takes -{max} .. {max} mm")]
    Range {
        what: &'static str,
        value: f64,
        max: f64,
    },
    /// A negative nose radius.
    #[error("nose radius must not be negative")]
    NegativeRadius,
    /// An imaginary tip number past 9.
    #[error("tip {0}: imaginary tip numbers are 0-9")]
    Tip(u8),
    /// A work offset index past G59.
    #[error("work offset {0}: G54-G59 are 0-5")]
    WorkIndex(usize),
    /// An axis the machine does not have.
    #[error("this machine has no axis '{0}'")]
    NoAxis(String),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_value_and_the_range() {
        let e = OffsetError::Range {
            what: "wear",
            value: 12.5,
            max: 9.999,
        };
        assert_eq!(
            e.to_string(),
            "wear 12.5: the page takes -9.999 .. 9.999 mm"
        );
        let e = OffsetError::BadKey {
            page: "h".into(),
            key: "one".into(),
        };
        assert_eq!(e.to_string(), "[h] key 'one' is not an offset number");
        assert_eq!(
            OffsetError::Number { n: 0, count: 99 }.to_string(),
            "offset number 0: this machine has 1-99"
        );
    }
}
