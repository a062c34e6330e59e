//! Stage one of parsing: [`RawArgs`] splits the arguments into the flags of the table and their
//! values. Flags are spelled as the course spells them, with a single dash (`-input FILE`,
//! `-size W H`, `-depth DMIN DMAX FILE`); no argument-parsing crate handles multi-value
//! single-dash flags in that style, so the parsing is written here.

use std::collections::BTreeMap;
use std::ffi::OsString;

use super::error::UsageError;
use super::flags::Flag;

/// Stage one of parsing: flags recognised, values collected, nothing interpreted.
#[derive(Debug, Clone, Default)]
pub struct RawArgs {
    values: BTreeMap<Flag, Vec<OsString>>,
}

impl RawArgs {
    /// Splits arguments (without the program name) into flags and values: unknown and repeated
    /// flags and missing values are usage errors.
    pub(crate) fn parse<I, S>(arguments: I) -> Result<Self, UsageError>
    where
        I: IntoIterator<Item = S>,
        S: Into<OsString>,
    {
        let mut arguments = arguments.into_iter().map(Into::into).peekable();
        let mut values = BTreeMap::new();
        while let Some(argument) = arguments.next() {
            let word = argument.to_string_lossy();
            let flag = match Flag::named(&word) {
                Some(flag) => flag,
                None if word.starts_with('-') && word.len() > 1 => {
                    return Err(UsageError::UnknownFlag(word.into_owned()));
                }
                None => return Err(UsageError::StrayArgument(word.into_owned())),
            };
            // Leading values that may be left out are given when the first is a number.
            let lead_left_out = flag.optional_lead() > 0
                && arguments
                    .peek()
                    .is_none_or(|next| next.to_string_lossy().parse::<f64>().is_err());
            let arity = flag.arity()
                - if lead_left_out {
                    flag.optional_lead()
                } else {
                    0
                };
            let mut flag_values = Vec::with_capacity(arity);
            for _ in 0..arity {
                // A value may start with '-' (a negative depth); a known flag may not be a value.
                let next_is_flag = arguments
                    .peek()
                    .is_some_and(|next| Flag::named(&next.to_string_lossy()).is_some());
                match arguments.next() {
                    Some(value) if !next_is_flag => flag_values.push(value),
                    next => {
                        return Err(UsageError::MissingValue {
                            flag,
                            needed: arity,
                            given: flag_values.len(),
                            next: next.map(|next| next.to_string_lossy().into_owned()),
                        });
                    }
                }
            }
            if values.insert(flag, flag_values).is_some() {
                return Err(UsageError::Repeated(flag));
            }
        }
        Ok(Self { values })
    }

    /// Whether `flag` was given.
    pub(crate) fn has(&self, flag: Flag) -> bool {
        self.values.contains_key(&flag)
    }

    /// How many values `flag` was given with (0 when absent).
    pub(crate) fn count(&self, flag: Flag) -> usize {
        self.values.get(&flag).map_or(0, Vec::len)
    }

    /// Value `index` of `flag`, if given.
    pub(crate) fn value(&self, flag: Flag, index: usize) -> Option<&OsString> {
        self.values.get(&flag).and_then(|values| values.get(index))
    }

    /// Value `index` of `flag` as text ("" when the flag is absent).
    pub(crate) fn text(&self, flag: Flag, index: usize) -> Result<&str, UsageError> {
        self.value(flag, index)
            .map(|value| value.to_str().ok_or(UsageError::NotText(flag)))
            .unwrap_or(Ok(""))
    }

    /// The one flag of `flags` that is given, if any; two of them are a conflict.
    pub(crate) fn one_of(&self, flags: &[Flag]) -> Result<Option<Flag>, UsageError> {
        let given: Vec<Flag> = flags.iter().copied().filter(|&f| self.has(f)).collect();
        match given.as_slice() {
            [] => Ok(None),
            [one] => Ok(Some(*one)),
            [first, second, ..] => Err(UsageError::Conflicting(*first, *second)),
        }
    }
}
