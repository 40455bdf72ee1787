//! Parquet files (PyProBE's processed recordings), read with the `parquet` crate (pure Rust,
//! without Arrow; LZ4, LZ4_RAW, Snappy or no compression: PyProBE's default `performance`
//! setting writes LZ4) into the delimited text every reader shares, one line per row with the
//! columns' names as header, so that a vendor layout ([`super::pyprobe`]) converts it.

use std::fs::File;
use std::path::Path;

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::Field;

/// Whether `bytes` open as a Parquet file does (`PAR1`).
pub fn is_parquet(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PAR1")
}

/// The rows of the Parquet file `path` as comma-separated text under a header of its column
/// names; numbers written so that they read back to the same `f64`.
pub fn to_text(path: &Path) -> Result<String, String> {
    let why = |e: parquet::errors::ParquetError| {
        format!("cannot read it as Parquet: {e} (read: LZ4, Snappy or uncompressed files, as PyProBE writes by default; save others with one of these)")
    };
    let file = File::open(path).map_err(|e| e.to_string())?;
    let reader = SerializedFileReader::new(file).map_err(why)?;
    let schema = reader.metadata().file_metadata().schema_descr_ptr();
    let names: Vec<&str> = schema.columns().iter().map(|c| c.name()).collect();
    if let Some(n) = names.iter().find(|n| n.contains(',')) {
        return Err(format!("column name `{n}` holds a comma"));
    }
    let mut text = names.join(",");
    text.push('\n');
    for row in reader.get_row_iter(None).map_err(why)? {
        let row = row.map_err(why)?;
        let fields: Vec<String> = row.get_column_iter().map(|(_, f)| field_text(f)).collect();
        text.push_str(&fields.join(","));
        text.push('\n');
    }
    Ok(text)
}

/// A value as the table reader reads it: numbers in Rust's shortest round-trip form, a
/// missing value empty, anything else as the crate prints it (commas removed).
fn field_text(f: &Field) -> String {
    match f {
        Field::Null => String::new(),
        Field::Double(v) => v.to_string(),
        Field::Float(v) => v.to_string(),
        Field::Long(v) => v.to_string(),
        Field::Int(v) => v.to_string(),
        other => other.to_string().replace(',', " "),
    }
}
