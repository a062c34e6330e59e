//! The way back from a request to the command line: [`RenderRequest::to_arguments`] writes a
//! request as the arguments that parse to it again (the viewer's exports and course files write
//! their command line with it), flags spelled by the table.

use std::ffi::OsString;

use super::flags::Flag;
use super::request::{FILTER_FLAGS, RenderRequest, SAMPLER_FLAGS};
use crate::render::Filter;
use crate::render::depth_map::DepthColourMap;

impl RenderRequest {
    /// The arguments (without the program name) that parse to this request again: every
    /// setting, flags spelled by the table. Numbers are written in their shortest exact form,
    /// so they parse back to the same values.
    pub fn to_arguments(&self) -> Vec<OsString> {
        let mut arguments: Vec<OsString> = Vec::new();
        let mut push = |flag: Flag, values: Vec<OsString>| {
            arguments.push(flag.name().into());
            arguments.extend(values);
        };
        push(Flag::Input, vec![self.input.clone().into()]);
        if self.size_given {
            push(
                Flag::Size,
                vec![
                    self.width_px.to_string().into(),
                    self.height_px.to_string().into(),
                ],
            );
        }
        for output in self.outputs.each() {
            // DMIN DMAX before the file, for the outputs that map depth.
            let mut values: Vec<OsString> = output.range.map_or_else(Vec::new, |range| {
                vec![
                    range.min_t.to_string().into(),
                    range.max_t.to_string().into(),
                ]
            });
            values.push(output.path.into());
            push(output.flag, values);
        }
        if self.depth_colour_map != DepthColourMap::Grey {
            push(
                Flag::DepthColourMap,
                vec![self.depth_colour_map.name().into()],
            );
        }
        if let Some(sampling) = &self.quality.sampling {
            let sampler_flag = SAMPLER_FLAGS
                .iter()
                .find(|(_, sampler)| *sampler == sampling.sampler)
                .map_or(Flag::UniformSamples, |(flag, _)| *flag);
            push(sampler_flag, vec![sampling.samples.to_string().into()]);
            if sampling.filter != Filter::PIXEL_BOX {
                let size = sampling.filter.size();
                let filter_flag = FILTER_FLAGS
                    .iter()
                    .find(|(_, make)| make(size) == sampling.filter)
                    .map_or(Flag::BoxFilter, |(flag, _)| *flag);
                push(filter_flag, vec![size.to_string().into()]);
            }
        }
        if let Some(compare) = &self.compare {
            if let Some(path) = &compare.colour {
                push(Flag::CompareOutput, vec![path.clone().into()]);
            }
            if let Some(depth) = &compare.depth {
                let mut values: Vec<OsString> = depth.range.map_or_else(Vec::new, |range| {
                    vec![
                        range.min_t.to_string().into(),
                        range.max_t.to_string().into(),
                    ]
                });
                values.push(depth.path.clone().into());
                push(Flag::CompareDepth, values);
            }
            if let Some(path) = &compare.diff {
                push(Flag::Diff, vec![path.clone().into()]);
            }
            if compare.json {
                push(Flag::CompareFormat, vec!["json".into()]);
            }
        }
        if let Some((x, y)) = self.trace {
            push(
                Flag::Trace,
                vec![x.to_string().into(), y.to_string().into()],
            );
        }
        if self.stats {
            push(Flag::Stats, Vec::new());
        }
        arguments
    }
}
