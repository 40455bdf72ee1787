//! Raw cycler exports (`tests/data/cycler/`, origins in its README): format detection, SI
//! units, discharge-positive current, step numbers and steps; the raw Basytec export of the
//! LG M50 C/2 discharge against its converted recording in `../shared/recordings/`.

use std::path::Path;

use cellstudio::data::Recording;
use cellstudio::data::cycler::{CyclerFormat, StepKind, detect, read, read_recording, read_str, steps};

fn sample(name: &str) -> std::path::PathBuf {
    Path::new("tests/data/cycler").join(name)
}

/// The raw Basytec rows behind every row of the converted recording: same time (after the
/// shift to the kept window), current (sign flipped), voltage and temperature (+273.15).
#[test]
fn raw_basytec_export_gives_the_converted_recording() {
    let converted = Path::new("../shared/recordings/lgm50_25C_0p5C_discharge_cell785.csv");
    if !converted.exists() {
        eprintln!("skipped: {} is absent (the team's shared folder is not beside the repo)", converted.display());
        return;
    }
    let conv = Recording::from_csv(converted).unwrap();
    let raw = read(&sample("basytec_lgm50_cell785_0p5C_trimmed.csv")).unwrap();
    assert_eq!(raw.format, CyclerFormat::Basytec);
    let r = &raw.recording;
    // Align at the start of the discharge: the first non-zero current in both.
    let start = |rec: &Recording| rec.time[rec.current.iter().position(|i| *i != 0.0).unwrap()];
    let shift = start(r) - start(&conv);
    let (rt, ct) = (r.temperature.as_ref().unwrap(), conv.temperature.as_ref().unwrap());
    for k in 0..conv.time.len() {
        let t = conv.time[k] + shift;
        let j = (0..r.time.len())
            .find(|&j| (r.time[j] - t).abs() < 1e-6 && r.current[j] == conv.current[k])
            .unwrap_or_else(|| panic!("converted row {k} (t = {} s, I = {} A) has no raw row", conv.time[k], conv.current[k]));
        assert_eq!(r.voltage[j], conv.voltage[k], "voltage at converted row {k}");
        assert!((rt[j] - ct[k]).abs() < 1e-9, "temperature at converted row {k}: {} vs {}", rt[j], ct[k]);
    }
    // The raw file has the step numbers: 10 rest, 13 the discharge.
    let st = steps(r, raw.step.as_deref());
    let discharge = st.iter().find(|s| s.kind == StepKind::Cc).unwrap();
    assert_eq!(discharge.cycler_step, Some(13));
    assert!((discharge.mean_current - 2.5).abs() < 0.002, "{}", discharge.mean_current);
    // The converted file's discharge lasts from 540.1 s to its cut-off.
    let conv_end = conv.time[conv.current.iter().rposition(|i| *i != 0.0).unwrap()];
    assert!((discharge.duration - (conv_end - 540.1)).abs() < 70.0, "{}", discharge.duration);
}

/// PyProBE's Parquet recording of the LG M50T (LZ4-compressed, as PyProBE writes by default)
/// read directly: the PyProBE layout, charge-positive current flipped, Celsius to kelvin,
/// the cycler's steps (3 rest, 4 rest, 5 the C/10 discharge); and every row of the converted
/// recording in `../shared/recordings/` within the sample's span has its raw row (the CSV is
/// rounded to 1 ms, 10 uA, 10 uV and 0.01 K: within half the last digit, and a raw value
/// that ends in that half, as 4.021225 V, may have been rounded either way).
#[test]
fn pyprobe_parquet_gives_the_converted_recording() {
    let raw = read(&sample("pyprobe_lgm50t_cellC_trimmed.parquet")).unwrap();
    assert_eq!(raw.format, CyclerFormat::PyProbe);
    let r = &raw.recording;
    assert_eq!(r.time.len(), 2143);
    let st = steps(r, raw.step.as_deref());
    let kinds: Vec<(Option<i64>, StepKind)> = st.iter().map(|s| (s.cycler_step, s.kind)).collect();
    assert_eq!(kinds, [(Some(3), StepKind::Rest), (Some(4), StepKind::Rest), (Some(5), StepKind::Cc)]);
    assert!((st[2].mean_current - 0.5).abs() < 1e-3, "C/10 discharge positive: {}", st[2].mean_current);
    let temperature = r.temperature.as_ref().unwrap();
    assert!(temperature.iter().all(|t| (296.0..301.0).contains(t)), "kelvin");
    let converted = Path::new("../shared/recordings/lgm50t_25C_C10_pocv_discharge_cellC.csv");
    if !converted.exists() {
        eprintln!("skipped the comparison: {} is absent (the team's shared folder is not beside the repo)", converted.display());
        return;
    }
    let conv = Recording::from_csv(converted).unwrap();
    // Align at the start of the discharge: the first non-zero current in both.
    let start = |rec: &Recording| rec.time[rec.current.iter().position(|i| *i != 0.0).unwrap()];
    let shift = start(r) - start(&conv);
    let ct = conv.temperature.as_ref().unwrap();
    // Half the last digit of a value written with `digits` decimals, and the binary rounding.
    let half = |digits: i32| 0.5 * 10f64.powi(-digits) + 1e-12;
    let mut compared = 0;
    for k in (0..conv.time.len()).filter(|&k| conv.time[k] + shift <= r.time[r.time.len() - 1]) {
        let t = conv.time[k] + shift;
        let j = (0..r.time.len())
            .find(|&j| (r.time[j] - t).abs() < 1e-3 && (r.current[j] - conv.current[k]).abs() <= half(5))
            .unwrap_or_else(|| panic!("converted row {k} (t = {} s, I = {} A) has no raw row", conv.time[k], conv.current[k]));
        assert!((r.voltage[j] - conv.voltage[k]).abs() <= half(5), "voltage at converted row {k}");
        assert!((temperature[j] - ct[k]).abs() <= half(2), "temperature at converted row {k}: {} vs {}", temperature[j], ct[k]);
        compared += 1;
    }
    eprintln!("{compared} converted rows compared");
    assert!(compared > 250, "{compared} rows compared");
}

/// A file that opens as Parquet but is not one is a parse error naming the file, not a panic.
#[test]
fn broken_parquet_is_an_error() {
    let tmp = tempfile::tempdir().unwrap();
    let path = tmp.path().join("broken.parquet");
    let mut bytes = std::fs::read(sample("pyprobe_lgm50t_cellC_trimmed.parquet")).unwrap();
    bytes.truncate(bytes.len() / 2);
    std::fs::write(&path, &bytes).unwrap();
    let e = read(&path).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("broken.parquet") && e.contains("Parquet"), "{e}");
}

/// The CC-CV charge of the same cell, logged by the Basytec as one step (9): split into a CC
/// step at C/3 up to 4.2 V and a CV step at 4.2 V whose current decays.
#[test]
fn real_cccv_charge_is_cc_then_cv() {
    let d = read(&sample("basytec_lgm50_cell785_cccv_trimmed.csv")).unwrap();
    let st = steps(&d.recording, d.step.as_deref());
    let kinds: Vec<(Option<i64>, StepKind)> = st.iter().map(|s| (s.cycler_step, s.kind)).collect();
    assert_eq!(kinds, [(Some(8), StepKind::Rest), (Some(9), StepKind::Cc), (Some(9), StepKind::Cv), (Some(10), StepKind::Rest)]);
    let (cc, cv) = (&st[1], &st[2]);
    assert!((cc.mean_current + 5.0 / 3.0).abs() < 0.01, "C/3 charge: {}", cc.mean_current);
    assert!((cc.end_voltage - 4.2).abs() < 0.005 && (cv.start_voltage - 4.2).abs() < 0.005 && (cv.end_voltage - 4.2).abs() < 0.005);
    let i = &d.recording.current;
    // The CV decays from the C/3 level to the C/20 cut-off (0.25 A).
    assert!(i[cv.first].abs() > 1.5 && (i[cv.last].abs() - 0.25).abs() < 0.01, "CV: {} -> {}", i[cv.first], i[cv.last]);
}

#[test]
fn basytec_result_file() {
    let d = read(&sample("basytec_pyprobe_sample.txt")).unwrap();
    assert_eq!(d.format, CyclerFormat::Basytec);
    let r = &d.recording;
    assert_eq!(r.time[0], 0.0);
    assert!((r.voltage[0] - 3.52575489148741).abs() < 1e-12);
    assert!((r.temperature.as_ref().unwrap()[0] - (25.47953 + 273.15)).abs() < 1e-9);
    assert!(d.step.as_ref().unwrap().iter().all(|s| *s >= 1));
}

#[test]
fn biologic_with_and_without_header_block() {
    let d = read(&sample("biologic_pyprobe_no_header.mpt")).unwrap();
    assert_eq!(d.format, CyclerFormat::BioLogic);
    assert!((d.time_offset - 2.816723801174285E+005).abs() < 1e-6);
    assert!((d.recording.voltage[0] - 2.9344745).abs() < 1e-12);
    let d = read(&sample("biologic_pyprobe_CA1_trimmed.txt")).unwrap();
    assert_eq!(d.format, CyclerFormat::BioLogic);
    assert_eq!(d.recording.time.len() + d.dropped_repeats, 57);
    assert!((d.recording.time[1] - 0.1).abs() < 1e-6);
    assert!((d.recording.voltage[0] - 3.5180547).abs() < 1e-12);
    assert!((d.recording.temperature.as_ref().unwrap()[0] - (22.185871 + 273.15)).abs() < 1e-9);
}

#[test]
fn biologic_current_is_charge_positive_in_the_file() {
    let text = "time/s\tEcell/V\tI/mA\tNs\n0\t3.7\t0\t0\n1\t3.6\t2500\t1\n2\t3.5\t-2500\t2\n";
    let d = read_str("inline", text).unwrap();
    assert_eq!(d.recording.current, vec![0.0, -2.5, 2.5]);
    assert_eq!(d.step, Some(vec![0, 1, 2]));
}

/// EC-Lab in a European locale: semicolons between fields, decimal commas.
#[test]
fn semicolon_exports_with_decimal_commas() {
    let text = "time/s;Ecell/V;I/mA;Ns\n0,0;3,7012;0,0;0\n1,5;3,6020;2500,0;1\n";
    let d = read_str("eu.csv", text).unwrap();
    assert_eq!(d.recording.time, vec![0.0, 1.5]);
    assert_eq!(d.recording.voltage, vec![3.7012, 3.602]);
    assert_eq!(d.recording.current, vec![0.0, -2.5]);
}

#[test]
fn maccor_signed_and_stated_currents() {
    let d = read(&sample("maccor_pyprobe_sample.csv")).unwrap();
    assert_eq!(d.format, CyclerFormat::Maccor);
    let r = &d.recording;
    let n = r.time.len() - 1;
    // PyProBE's expected last row: 13.06 s, step 2, 28.798 A (charge), 3.716 V, 22.2591 °C.
    assert_eq!((r.time[n], r.current[n], r.voltage[n]), (13.06, -28.798, 3.716));
    assert_eq!(d.step.as_ref().unwrap()[n], 2);
    assert!((r.temperature.as_ref().unwrap()[n] - 295.4091).abs() < 1e-9);
    let d = read(&sample("maccor_documented_layout.txt")).unwrap();
    assert_eq!(d.format, CyclerFormat::Maccor);
    assert_eq!(d.recording.current, vec![0.0, 0.0, 7.5, 7.5, 7.5, 0.0, 0.0, -2.5, -2.5]);
    let kinds: Vec<StepKind> = steps(&d.recording, d.step.as_deref()).iter().map(|s| s.kind).collect();
    assert_eq!(kinds, [StepKind::Rest, StepKind::Pulse, StepKind::Rest, StepKind::Pulse]);
}

#[test]
fn neware_documented_layout() {
    let d = read(&sample("neware_documented_layout.csv")).unwrap();
    assert_eq!(d.format, CyclerFormat::Neware);
    let r = &d.recording;
    assert_eq!(r.time.len(), 9);
    assert!((r.time[3] - 60.1).abs() < 1e-9 && (r.time[8] - 180.2).abs() < 1e-9);
    assert!((r.current[4] - 2.5001).abs() < 1e-12, "discharge positive, mA -> A: {}", r.current[4]);
    assert!((r.temperature.as_ref().unwrap()[0] - 298.25).abs() < 1e-9);
    let st = steps(r, d.step.as_deref());
    let kinds: Vec<(Option<i64>, StepKind)> = st.iter().map(|s| (s.cycler_step, s.kind)).collect();
    assert_eq!(kinds, [(Some(1), StepKind::Rest), (Some(2), StepKind::Cc), (Some(3), StepKind::Rest)]);
    assert!((st[1].duration - 90.1).abs() < 1e-9);
}

#[test]
fn arbin_export() {
    let d = read(&sample("arbin_pyprobe_sample.csv")).unwrap();
    assert_eq!(d.format, CyclerFormat::Arbin);
    let r = &d.recording;
    assert_eq!(d.time_offset, 30.0005);
    assert!((r.time[11] - (300.6979 - 30.0005)).abs() < 1e-9);
    assert_eq!(r.current[11], -2.647604);
    assert_eq!(d.step.as_ref().unwrap()[11], 3);
    assert!((r.temperature.as_ref().unwrap()[0] - (24.66422 + 273.15)).abs() < 1e-9);
}

#[test]
fn detection_and_native_files() {
    assert_eq!(detect("time_s,current_A,voltage_V\n0,0,4\n"), Some(CyclerFormat::Native));
    let d = read(Path::new("tests/data/spm_contact_resistance_seed.csv")).unwrap();
    assert_eq!(d.format, CyclerFormat::Native);
    let native = Recording::from_csv(Path::new("tests/data/spm_contact_resistance_seed.csv")).unwrap();
    assert_eq!(d.recording.voltage, native.voltage);
    assert_eq!(d.recording.time, native.time);
    // `--data` reads a raw export with the default format.
    let r = read_recording(&sample("arbin_pyprobe_sample.csv"), &Default::default()).unwrap();
    assert_eq!(r.current[11], -2.647604);
}

#[test]
fn errors_name_the_line_column_and_value() {
    let e = read_str("x.csv", "time/s\tEcell/V\tI/mA\n0\t3.7\t0\n1\tabc\t0\n").unwrap_err().to_string();
    assert!(e.contains("BioLogic") && e.contains("line 3") && e.contains("`Ecell/V` = `abc`"), "{e}");
    let e = read_str("x.csv", "time/s\tEcell/V\tI/mA\n5\t3.7\t0\n1\t3.7\t0\n").unwrap_err().to_string();
    assert!(e.contains("line 3") && e.contains("goes back in time"), "{e}");
    let e = read_str("x.csv", "Rec,Step,Test Time (sec),Voltage\n1,1,0,3.7\n").unwrap_err().to_string();
    assert!(e.contains("no current column") && e.contains("Amps"), "{e}");
    let e = read_str("x.csv", "a,b\n1,2\n").unwrap_err().to_string();
    assert!(e.contains("not a known cycler export"), "{e}");
    let e = read_str("x.csv", "time_s,current_A,voltage_V\n0,0,3700\n1,0,3.7\n").unwrap_err().to_string();
    assert!(e.contains("line 2") && e.contains("not a cell voltage"), "{e}");
}
