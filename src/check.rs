//! Homework answers: reading a matrix as the book prints it, and finding the
//! cells that differ from zsim's.

/// A matrix read from an answer file, top row first.
pub type Matrix = Vec<Vec<u32>>;

/// Reads an answer: whitespace-separated integers, top row first, one row a
/// line; blank lines and lines starting with `#` are ignored. Checks the
/// shape against the raster; the error says what was found.
pub fn parse_answer(text: &str, width: u32, height: u32) -> Result<Matrix, String> {
    let mut rows = Vec::new();
    for (line_number, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let row: Result<Vec<u32>, String> = trimmed
            .split_whitespace()
            .enumerate()
            .map(|(column, cell)| {
                cell.parse::<u32>().map_err(|_| {
                    format!(
                        "line {}, value {}: \"{cell}\" is not a whole number from 0 to 4294967295",
                        line_number + 1,
                        column + 1
                    )
                })
            })
            .collect();
        let row = row?;
        if row.len() != width as usize {
            let plural = if row.len() == 1 { "" } else { "s" };
            return Err(format!("line {}: {} value{plural}; the raster is {width} wide", line_number + 1, row.len()));
        }
        rows.push(row);
    }
    if rows.len() != height as usize {
        return Err(format!("{} rows; the raster has {height}", rows.len()));
    }
    Ok(rows)
}

/// One cell where the answer differs from zsim.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mismatch {
    /// Column.
    pub x: u32,
    /// Row (0 at the bottom).
    pub y: u32,
    /// The answer's value.
    pub answer: u32,
    /// zsim's value.
    pub expected: u32,
}

/// The cells where `answer` differs from `expected` (both top row first),
/// in reading order: top row first, left to right.
pub fn compare(answer: &Matrix, expected: &Matrix) -> Vec<Mismatch> {
    let height = expected.len() as u32;
    let mut mismatches = Vec::new();
    for (i, (answer_row, expected_row)) in answer.iter().zip(expected).enumerate() {
        for (x, (&a, &e)) in answer_row.iter().zip(expected_row).enumerate() {
            if a != e {
                mismatches.push(Mismatch { x: x as u32, y: height - 1 - i as u32, answer: a, expected: e });
            }
        }
    }
    mismatches
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_and_blank_lines_are_ignored() {
        let text = "# my answer\n\n1 2\n\n3 4\n";
        assert_eq!(parse_answer(text, 2, 2).unwrap(), vec![vec![1, 2], vec![3, 4]]);
    }

    #[test]
    fn wrong_shapes_say_what_was_found() {
        assert_eq!(parse_answer("1 2\n3 4\n5 6\n", 2, 2).unwrap_err(), "3 rows; the raster has 2");
        assert_eq!(parse_answer("1 2\n3\n", 2, 2).unwrap_err(), "line 2: 1 value; the raster is 2 wide");
        assert_eq!(
            parse_answer("1 x\n", 2, 1).unwrap_err(),
            "line 1, value 2: \"x\" is not a whole number from 0 to 4294967295"
        );
    }

    #[test]
    fn mismatches_name_cells_with_y_up() {
        let expected = vec![vec![0, 0], vec![0, 5]];
        let answer = vec![vec![0, 1], vec![0, 5]];
        assert_eq!(compare(&answer, &expected), vec![Mismatch { x: 1, y: 1, answer: 1, expected: 0 }]);
    }
}
