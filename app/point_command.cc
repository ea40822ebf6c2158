// The material-point driver command.
#include "app/point_command.h"

#include "deck/deck_reader.h"
#include "materials/material_registry.h"
#include "materials/point_driver.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <map>
#include <sstream>
#include <stdexcept>

namespace vulnus::app
{
using deck::DeckError;
using deck::RunParameters;
using deck::read_run_parameters;

namespace
{
struct PointOptions
{
  std::string deck, material, deformation, path, output;
  double max_value = 0.0;
  int n_steps = 0;
  bool have_fiber = false;
  materials::Vector3 fiber = materials::Vector3::UnitX();
};

double parse_number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0.0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value))
    throw std::invalid_argument(option + ": '" + text + "' is not a number");
  return value;
}

PointOptions parse(const std::vector<std::string>& args)
{
  PointOptions o;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size())
        throw std::invalid_argument(a + ": missing value");
      return args[++i];
    };
    if (a == "--material")
      o.material = value();
    else if (a == "--deformation")
      o.deformation = value();
    else if (a == "--path")
      o.path = value();
    else if (a == "--max")
      o.max_value = parse_number(a, value());
    else if (a == "--steps")
    {
      const double steps = parse_number(a, value());
      if (steps < 1 || steps > 1e7 || steps != static_cast<int>(steps))
        throw std::invalid_argument("--steps: expected a whole number in [1, 1e7]");
      o.n_steps = static_cast<int>(steps);
    }
    else if (a == "--output")
      o.output = value();
    else if (a == "--fiber")
    {
      std::stringstream in(value());
      std::string part;
      int d = 0;
      while (std::getline(in, part, ','))
      {
        if (d == 3)
          throw std::invalid_argument("--fiber: expected three comma-separated numbers x,y,z");
        o.fiber[d++] = parse_number("--fiber", part);
      }
      if (d != 3 || o.fiber.norm() == 0.0)
        throw std::invalid_argument("--fiber: expected a non-zero vector x,y,z");
      o.fiber.normalize();
      o.have_fiber = true;
    }
    else if (!a.empty() && a[0] == '-')
      throw std::invalid_argument("unknown option '" + a + "'");
    else if (o.deck.empty())
      o.deck = a;
    else
      throw std::invalid_argument("unexpected argument '" + a + "'");
  }
  if (o.deck.empty())
    throw std::invalid_argument("missing DECK.prm");
  if (o.material.empty())
    throw std::invalid_argument("missing --material NAME");
  if (o.output.empty())
    throw std::invalid_argument("missing --output OUT.csv");
  if (o.deformation.empty() == o.path.empty())
    throw std::invalid_argument("give either --deformation F.csv or --path NAME --max V --steps N");
  if (!o.path.empty() && o.n_steps == 0)
    throw std::invalid_argument("--path needs --steps N (and --max V)");
  return o;
}
} // namespace

std::string point_usage()
{
  std::string paths;
  for (const std::string& name : materials::built_in_path_names())
    paths += (paths.empty() ? "" : ", ") + name;
  return "usage: vulnus point DECK.prm --material NAME --output OUT.csv\n"
         "         (--deformation F.csv | --path NAME --max VALUE --steps N) [--fiber x,y,z]\n"
         "  F.csv header F11,F12,F13,F21,F22,F23,F31,F32,F33, one row per step\n"
         "  built-in paths: " + paths + "\n";
}

int point_command(const std::vector<std::string>& arguments)
{
  PointOptions options;
  try
  {
    options = parse(arguments);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "vulnus point: error: " << e.what() << "\n\n" << point_usage();
    return 2;
  }
  std::unique_ptr<materials::Material> material;
  std::vector<materials::Tensor2> history;
  try
  {
    const RunParameters parameters = read_run_parameters(options.deck);
    const mpm::NamedMaterial* found = nullptr;
    std::string names;
    for (const mpm::NamedMaterial& m : parameters.scene.materials)
    {
      names += (names.empty() ? "" : ", ") + m.name;
      if (m.name == options.material)
        found = &m;
    }
    if (!found)
      throw std::invalid_argument("--material: no material '" + options.material + "' in " +
                                  options.deck + "; the deck has: " + names);
    material = materials::create_material(found->parameters);
    history = options.deformation.empty()
                ? materials::built_in_path(options.path, options.max_value, options.n_steps, options.fiber)
                : materials::read_deformation_csv_file(options.deformation);
  }
  catch (const DeckError& e)
  {
    for (const std::string& m : e.messages())
      std::cerr << "vulnus point: error: " << m << '\n';
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vulnus point: error: " << e.what() << '\n';
    return 2;
  }
  try
  {
    const auto rows = materials::drive_point(*material, history, options.fiber);
    materials::write_response_csv_file(options.output, rows);
    std::cout << "wrote " << rows.size() << " rows to " << options.output << '\n';
  }
  catch (const std::exception& e)
  {
    std::cerr << "vulnus point: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
} // namespace vulnus::app
