/**
 * @file
 * libFuzzer harness of the Gmsh frame reader (read_gmsh_frame) and of the
 * frame built from it: the input is written to a scratch `.msh` file and
 * read; if it holds a frame, that frame is built as `Model/Type = frame`
 * with `Model/Frame/Mesh file` pointing to it and one section and material
 * for every member (Member properties), then decomposed by member as the
 * coupled method does. Errors thrown as exceptions are the expected outcome
 * of bad input; crashes, sanitizer reports, hangs and other exceptions are
 * findings. Run by bench/fuzz.sh.
 */
#include <deal.II/base/parameter_handler.h>

#include <hati/model/decomposition.h>
#include <hati/model/discrete_system.h>
#include <hati/model/gmsh_frame_reader.h>
#include <hati/model/model.h>

#include "fuzz_common.h"

#include <exception>

namespace
{
std::string mesh_file;

/** Whether @p name survives the `name: values; ...` syntax of Member properties. */
bool plain_name(const std::string &name)
{
  return !name.empty() && name.size() < 64 &&
         name.find_first_of(":;,\\\n\r\t #") == std::string::npos;
}

/** Build the frame of @p mesh through the .prm front end. */
void build_frame(const hati::GmshFrame &mesh)
{
  // legitimately large frames are slow, not wrong: skip them
  std::size_t n_elements = 0;
  for (const auto &[name, path] : mesh.members)
    n_elements += path.size();
  if (n_elements > 2000 || mesh.members.size() > 64)
    return;
  std::string properties;
  for (const auto &[name, path] : mesh.members)
  {
    if (!plain_name(name))
      return;
    properties += name + ": rect, steel; ";
  }
  dealii::ParameterHandler prm;
  hati::declare_model_parameters(prm);
  prm.parse_input_from_string("subsection Model\n"
                              "  set Type = frame\n"
                              "  subsection Frame\n"
                              "    set Materials = steel: 2.1e11, 0.3, 7850\n"
                              "    set Sections = rect: rectangle, 0.1, 0.2\n"
                              "  end\n"
                              "end\n");
  prm.enter_subsection("Model");
  prm.enter_subsection("Frame");
  prm.set("Mesh file", mesh_file);
  prm.set("Member properties", properties);
  prm.leave_subsection();
  prm.leave_subsection();

  hati::CommonModelParameters common;
  common.parse_parameters(prm);
  const auto model = hati::create_model(prm);
  hati::DiscreteSystem system;
  model->build(common, system);
  hati::check_finite(system);

  hati::DecompositionParameters parameters;
  parameters.members.push_back(mesh.members.begin()->first);
  hati::Decomposition decomposition;
  hati::decompose(*model, common, parameters, decomposition);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  hati::fuzz::silence_stdout();
  mesh_file = hati::fuzz::scratch_file(".msh");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  hati::fuzz::write_file(mesh_file, data, size);
  try
  {
    const hati::GmshFrame mesh = hati::read_gmsh_frame(mesh_file);
    build_frame(mesh);
  }
  catch (const std::exception &)
  {
    // a one-line error: the expected outcome of bad input
  }
  return 0;
}
