//! Unit tests of the command line: parsing, validation, messages, writing a request back.

use super::*;
use crate::render::depth_map::{DepthColourMap, DepthRange};
use crate::render::{Filter, Quality, Sampler, Sampling};

fn parse(line: &str) -> Result<Command, UsageError> {
    parse_command(line.split_whitespace())
}

#[test]
fn course_command_line_gives_a_render_request() {
    let command =
        parse("-input scene1_01.txt -size 200 100 -output out.tga -depth 9 10 depth.tga").unwrap();
    assert_eq!(
        command,
        Command::Render(Box::new(RenderRequest {
            input: "scene1_01.txt".into(),
            width_px: 200,
            height_px: 100,
            size_given: true,
            compare: None,
            outputs: Outputs {
                colour: Some("out.tga".into()),
                depth: Some(DepthOutput {
                    range: DepthRange::new(9.0, 10.0),
                    path: "depth.tga".into()
                }),
                depth16: None,
                depth_raw: None,
            },
            depth_colour_map: DepthColourMap::Grey,
            quality: Quality::default(),
            stats: false,
            trace: None,
        }))
    );
}

#[test]
fn negative_depth_values_are_values_not_flags() {
    let Command::Render(request) = parse("-input a.txt -depth -2 2 d.png").unwrap() else {
        panic!("expected a render request");
    };
    assert_eq!(
        request.outputs.depth.unwrap().range,
        DepthRange::new(-2.0, 2.0)
    );
    assert_eq!((request.width_px, request.height_px), DEFAULT_SIZE_PX);
}

#[test]
fn the_compare_depth_range_may_be_left_out() {
    let their_depth = |line: &str| match parse(line) {
        Ok(Command::Render(request)) => Ok(request.compare.unwrap().depth.unwrap()),
        Ok(other) => panic!("{other:?}"),
        Err(error) => Err(error.to_string()),
    };
    let given = their_depth("-input a.txt -compare_depth -2 2 d.png -diff x.png").unwrap();
    assert_eq!(given.range, Some(DepthRange::new(-2.0, 2.0)));
    assert_eq!(given.path, std::path::Path::new("d.png"));
    let left_out = their_depth("-input a.txt -compare_depth d.png -diff x.png").unwrap();
    assert_eq!(left_out.range, None);
    assert_eq!(left_out.path, std::path::Path::new("d.png"));
    // A flag is no file; one number is a range cut short.
    for line in [
        "-input a.txt -compare_depth -diff x.png",
        "-input a.txt -compare_depth 8 -diff x.png",
        "-input a.txt -compare_depth",
    ] {
        let error = their_depth(line).unwrap_err();
        assert!(error.contains("-compare_depth"), "{line}: {error}");
    }
}

#[test]
fn course_sampling_flags_give_a_sampling() {
    let Command::Render(request) =
        parse("-input a.txt -output x.png -jittered_samples 16 -gaussian_filter 0.8 -stats")
            .unwrap()
    else {
        panic!("expected a render request");
    };
    let sampling = request.quality.sampling.unwrap();
    assert_eq!(sampling.sampler, Sampler::Jittered);
    assert_eq!(sampling.samples, 16);
    assert_eq!(sampling.filter, Filter::Gaussian { sigma: 0.8 });
    assert!(request.stats);
    let Command::Render(request) = parse("-input a.txt -output x.png").unwrap() else {
        panic!("expected a render request");
    };
    assert_eq!(
        request.quality.sampling, None,
        "no flags: one centre sample"
    );
}

#[test]
fn without_outputs_the_viewer_opens() {
    assert_eq!(parse("").unwrap(), Command::View(ViewerRequest::default()));
    assert_eq!(
        parse("-input a.txt -size 640 480").unwrap(),
        Command::View(ViewerRequest {
            input: Some("a.txt".into()),
            size_px: Some((640, 480)),
            program: None,
        })
    );
    assert_eq!(parse("-help").unwrap(), Command::Help);
    assert_eq!(parse("--help").unwrap(), Command::Help);
}

#[test]
fn mistakes_are_usage_errors() {
    let cases = [
        ("-inptu a.txt", "unknown flag '-inptu'"),
        ("a.txt", "unexpected argument 'a.txt'"),
        (
            "-input",
            "-input needs a value (-input FILE); found none, then the end of the command",
        ),
        (
            "-input a.txt -size 200",
            "-size needs 2 values (-size W H); found 1, then the end",
        ),
        (
            "-input a.txt -size 200 -output x.tga",
            "-size needs 2 values (-size W H); found 1, then '-output'",
        ),
        (
            "-input a.txt -output -",
            "'-': outputs are written to files, not standard output; name a file ending in one of .tga, .png",
        ),
        (
            "-input a.txt -compare_output -",
            "'-': images to compare are read from files, not standard input; name a file ending in one of .tga, .png",
        ),
        (
            "-input a.txt -size 0 200 -output x.tga",
            "out of range: each side from 1 to 16384 pixels",
        ),
        ("-input a.txt -size 20000 200 -output x.tga", "out of range"),
        (
            "-input a.txt -size 99999999999 200 -output x.tga",
            "out of range",
        ),
        (
            "-input a.txt -size -5 200 -output x.tga",
            "expected a whole number",
        ),
        (
            "-input a.txt -size 2.5 200 -output x.tga",
            "expected a whole number",
        ),
        (
            "-input a.txt -depth a 1 d.tga",
            "expected a number (DMIN), found 'a'",
        ),
        (
            "-input a.txt -depth 1 inf d.tga",
            "expected a number (DMAX), found 'inf'",
        ),
        ("-input a.txt -output x.jpg", "unknown format"),
        ("-input a.txt -depth_raw x.png", "use one of .pfm, .exr"),
        ("-input a.txt -depth16 0 1 x.tga", "use one of .png"),
        ("-input a.txt -output x.png -depth16 0 1 x.png", "same file"),
        (
            "-input a.txt -depth_raw d.pfm -depth_colormap jet",
            "expected grey, turbo or viridis, found 'jet'",
        ),
        ("-input a.txt -output x.tga -output y.tga", "given twice"),
        ("-input a.txt -output x.tga -depth 1 2 x.tga", "same file"),
        ("-output x.tga", "need -input"),
        (
            "-input a.txt -output x.tga -precision f32",
            "unknown flag '-precision'",
        ),
    ];
    for (line, message) in cases {
        let error = parse(line).expect_err(line).to_string();
        assert!(error.contains(message), "{line}: {error}");
    }
}

#[test]
fn depth_outputs_and_colour_map() {
    let Command::Render(request) =
        parse("-input a.txt -depth_raw t.exr -depth16 -1 2.5 d16.png -depth_colormap viridis")
            .unwrap()
    else {
        panic!("a render request");
    };
    assert_eq!(request.outputs.depth_raw, Some("t.exr".into()));
    assert_eq!(
        request.outputs.depth16,
        Some(DepthOutput {
            range: DepthRange::new(-1.0, 2.5),
            path: "d16.png".into()
        })
    );
    assert_eq!(request.depth_colour_map, DepthColourMap::Viridis);
    assert!(request.outputs.colour.is_none() && request.outputs.depth.is_none());
}

/// A request with every setting, and variations of its sampling.
fn requests_with_every_setting() -> Vec<RenderRequest> {
    let full = RenderRequest {
        input: "class/my scene.txt".into(),
        width_px: 640,
        height_px: 360,
        size_given: true,
        compare: Some(CompareRequest {
            colour: Some("theirs/colour.tga".into()),
            depth: Some(TheirDepth {
                range: Some(DepthRange::new(9.0, 10.25)),
                path: "theirs/depth.png".into(),
            }),
            diff: Some("out/diff.png".into()),
            json: false,
        }),
        outputs: Outputs {
            colour: Some("out/colour.png".into()),
            depth: Some(DepthOutput {
                range: DepthRange::new(-0.1, 1.0 / 3.0),
                path: "out/depth.tga".into(),
            }),
            depth16: Some(DepthOutput {
                range: DepthRange::new(1e-300, 7e12),
                path: "out/depth16.png".into(),
            }),
            depth_raw: Some("out/t.exr".into()),
        },
        depth_colour_map: DepthColourMap::Viridis,
        quality: Quality {
            sampling: Some(Sampling {
                sampler: Sampler::Jittered,
                samples: 16,
                filter: Filter::Gaussian { sigma: 0.7 },
                seed: 0,
            }),
        },
        stats: true,
        trace: Some((3, 7)),
    };
    let mut requests = vec![
        full.clone(),
        RenderRequest {
            outputs: Outputs {
                depth_raw: full.outputs.depth_raw.clone(),
                ..Outputs::default()
            },
            depth_colour_map: DepthColourMap::Grey,
            quality: Quality::default(),
            stats: false,
            ..full.clone()
        },
        // A comparison alone, its size taken from the images, the depth range from the image.
        RenderRequest {
            width_px: 200,
            height_px: 200,
            size_given: false,
            outputs: Outputs::default(),
            compare: Some(CompareRequest {
                colour: None,
                depth: Some(TheirDepth {
                    range: None,
                    path: "mine.tga".into(),
                }),
                diff: None,
                json: false,
            }),
            ..full.clone()
        },
    ];
    for sampler in Sampler::ALL {
        for filter in [
            Filter::PIXEL_BOX,
            Filter::Box { radius: 1.25 },
            Filter::Tent { radius: 0.1 },
            Filter::Gaussian { sigma: 2.0 },
        ] {
            let mut request = full.clone();
            request.quality.sampling = Some(Sampling {
                sampler,
                samples: 9,
                filter,
                seed: 0,
            });
            requests.push(request);
        }
    }
    requests
}

#[test]
fn a_request_written_back_to_arguments_parses_to_the_same_request() {
    for request in requests_with_every_setting() {
        let arguments = request.to_arguments();
        // Every flag written is spelled as the table spells it.
        for word in &arguments {
            let word = word.to_string_lossy();
            if word.starts_with('-') && word.parse::<f64>().is_err() {
                assert!(Flag::named(&word).is_some(), "{word}");
            }
        }
        assert_eq!(
            parse_command(arguments.clone()),
            Ok(Command::Render(Box::new(request.clone()))),
            "{arguments:?}"
        );
    }
}

#[test]
fn the_course_command_alone_is_streamed() {
    let streams = |line: &str| match parse(line).unwrap() {
        Command::Render(request) => streamed::streams(&request),
        _ => panic!("{line}: expected a render request"),
    };
    for line in [
        "-input a.txt -output c.tga -depth 9 10 d.tga",
        "-input a.txt -size 30 20 -output c.TGA",
        "-input a.txt -depth 9 10 d.tga -depth_colormap turbo",
    ] {
        assert!(streams(line), "{line}");
    }
    for line in [
        "-input a.txt -output c.png -depth 9 10 d.tga",
        "-input a.txt -output c.tga -depth 9 10 d.png",
        "-input a.txt -output c.tga -uniform_samples 4",
        "-input a.txt -output c.tga -depth16 9 10 d.png",
        "-input a.txt -output c.tga -depth_raw d.pfm",
        "-input a.txt -output c.tga -compare_output theirs.tga",
        "-input a.txt -depth_raw d.pfm",
    ] {
        assert!(!streams(line), "{line}");
    }
}
