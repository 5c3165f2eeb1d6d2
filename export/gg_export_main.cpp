// gg-export: an H5MD particle file (gg-sim's snapshots) as GSD (HOOMD, freud, OVITO), extended XYZ
// (OVITO, ASE) or a LAMMPS dump (OVITO, LAMMPS tools), one frame per snapshot.
// Thin main: CLI11 -> the frames read one at a time -> a FrameSink -> the file published whole.
#include <optional>

#include "frame_sink.hpp"
#include "gg/cli.hpp"
#include "gg/errors.hpp"
#include "gg/frames.hpp"
#include "gg/h5file.hpp"
#include "gg/progress.hpp"
#include "gg/trajectory.hpp"

int main(int argc, char** argv) {
  return gg::guarded_main("gg-export", [&] {
    std::string input, output, format;
    std::vector<long> frames;
    CLI::App app{"gg-export: an H5MD particle file as GSD (HOOMD schema), extended XYZ or a LAMMPS dump, one frame "
                 "per snapshot. GSD centres positions on the box (HOOMD's convention); XYZ and LAMMPS keep [0, L). "
                 "A 1D run is written as a strip one diameter wide.",
                 "gg-export"};
    gg::CommonFlags common;
    gg::add_common_flags(app, common);
    app.add_option("input", input, "H5MD particle file written by gg-sim ('-' = stdin)")->required();
    app.add_option("-o,--output", output, "Output file ('-' = stdout; then give --format)")->required();
    app.add_option("--format", format, "gsd, xyz or lammps (default: from the output's extension: .gsd, .xyz, "
                   ".dump or .lammpstrj)");
    gg::add_list_option(app, "--frames", frames, "Comma-separated snapshot indices (negative from the end; default: all)");
    if (const int status = gg::parse_cli(app, argc, argv); status >= 0) return status;

    const gg::exporter::Format f = gg::exporter::output_format(output, format);
    gg::require_output_is_not_an_input(output, {input});
    gg::H5Input in(input);
    const std::string positions = "/particles/all/position/value";
    if (in.is_dataset(positions) && !in.shape(positions).empty() && in.shape(positions)[0] == 0)
      throw gg::RuntimeError("'" + in.path() + "' holds no snapshots; run gg-sim with --snapshots or "
                             "--snapshots-per-decade");
    gg::read_snapshots(in, {0});  // checks that the file is H5MD with positions (clear errors otherwise)
    const std::vector<long> chosen = gg::chosen_frames(frames, static_cast<long>(in.shape(positions)[0]), in.path());

    gg::OutputFile file(output, f == gg::exporter::Format::kGsd);
    const std::unique_ptr<gg::exporter::FrameSink> sink =
        f == gg::exporter::Format::kGsd   ? gg::exporter::gsd_sink(file, "gg-export")
        : f == gg::exporter::Format::kXyz ? gg::exporter::xyz_sink(file)
                                          : gg::exporter::lammps_sink(file);
    gg::Progress progress(common.show_progress(), "gg-export");
    // An aggregating run's radii and masses per snapshot (docs/DESIGN.md "Aggregates").
    const std::string radii = "/particles/all/radius/value", masses = "/particles/all/mass/value";
    const bool sizes = in.is_dataset(radii) && in.is_dataset(masses);
    // A sheared run's rate (docs/DESIGN.md "Files"): each frame's box is triclinic.
    const double shear_rate = in.attr_double("/parameters", "shear_rate").value_or(0.0);
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      const gg::Snapshots s = gg::read_snapshots(in, {chosen[k]});  // one frame in memory at a time
      const auto row = static_cast<std::size_t>(chosen[k]);
      const std::vector<double> radius = sizes ? in.read_rows(radii, {row}).data : std::vector<double>{};
      const std::vector<double> mass = sizes ? in.read_rows(masses, {row}).data : std::vector<double>{};
      sink->frame({s.dim, s.edges, s.periodic, shear_rate, s.n_particles, s.time[0], s.step[0], s.position.data(),
                   s.velocity.empty() ? nullptr : s.velocity.data(), s.image.empty() ? nullptr : s.image.data(),
                   sizes ? radius.data() : nullptr, sizes ? mass.data() : nullptr});
      progress.update(static_cast<double>(k + 1) / static_cast<double>(chosen.size()));
    }
    sink->finish();
    file.commit();
    return 0;
  });
}
