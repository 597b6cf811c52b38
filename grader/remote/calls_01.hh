#pragma once
/// \file
/// \brief Stage 01's calls across the connection: one operation per function of the
/// contract (stage_01.hh) and per virtual member of the objects it makes. The judge's
/// stand-ins (judge_01.cc) make these calls; the subject (subject_01.cc) serves them with
/// the student's code. Arguments and results cross in the order each line says.
#include "channel.hh"

namespace vl::remote::calls_01 {

enum op : op_id {
    translate_matrix,   ///< vector -> matrix
    scale_matrix,       ///< double, double, double -> matrix
    rotate_x_matrix,    ///< double -> matrix
    rotate_y_matrix,    ///< double -> matrix
    rotate_z_matrix,    ///< double -> matrix
    rotate_matrix,      ///< vector, double -> matrix
    shear_matrix,       ///< double, double -> matrix
    look_at_matrix,     ///< point, point, vector -> matrix
    inverse,            ///< matrix -> matrix
    make_pinhole_camera,  ///< camera_settings, int, int -> handle of a camera
    make_sampler,       ///< string -> handle of a sampler (0: nullptr)
    primary_ray,        ///< camera handle, double x, double y -> ray
    offsets,            ///< sampler handle, the span's values (vector of sample_offset), seed -> the span's values
    offsets_each,       ///< sampler handle, the span's first values, vector of seeds -> the span's values for each seed
};

/// The most offsets one call to a sampler crosses with (the tests ask for at most a few
/// thousand at once).
inline constexpr std::size_t max_offsets = 1 << 20;

}  // namespace vl::remote::calls_01
