// enum_option.h - an option whose value is one of a few names, stored as an enum.
//
// CLI11's own enum support prints a uint8_t enum's values as characters in --help and in
// its errors; this keeps the names in both.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "shpack/option_choices.h"

namespace shpack::cli {

template <class Enum>
CLI::Option* add_enum_option(CLI::App& cmd, const std::string& name, Enum& target,
                             const std::vector<std::pair<std::string, Enum>>& choices,
                             const std::string& help) {
  std::vector<std::string> names;
  std::string type_name;
  for (const auto& [choice, value] : choices) {
    names.push_back(choice);
    type_name += (type_name.empty() ? "" : "|") + choice;
  }
  // As a transform (not a check), IsMember rewrites "CENTER" to "center" for the callback;
  // the choices are shown once, by the type name.
  return cmd
      .add_option_function<std::string>(
          name,
          [&target, choices](const std::string& text) {
            for (const auto& [choice, value] : choices)
              if (choice == text) target = value;
          },
          help)
      ->transform(CLI::IsMember(names, CLI::ignore_case).description(""))
      ->type_name(type_name);
}

// The same, for one of the core's tables of names (option_choices.h).
template <class Enum, std::size_t N>
CLI::Option* add_enum_option(CLI::App& cmd, const std::string& name, Enum& target,
                             const std::array<OptionChoice<Enum>, N>& choices, const std::string& help) {
  std::vector<std::pair<std::string, Enum>> pairs;
  for (const OptionChoice<Enum>& choice : choices) pairs.emplace_back(std::string(choice.name), choice.value);
  return add_enum_option(cmd, name, target, pairs, help);
}

}  // namespace shpack::cli
