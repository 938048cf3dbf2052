// ewaview-docs: writes docs/user/options.md and keys.md from the option and key tables.
#include <fstream>
#include <iostream>
#include <string>

#include "app/options_markdown.h"
#include "ui/keys_markdown.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: ewaview-docs FOLDER (docs/user: writes options.md and keys.md there)\n";
    return 2;
  }
  const std::string folder = argv[1];
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"options.md", ewa::optionsMarkdown()},
        {"keys.md", ewa::keysMarkdown()}}) {
    std::ofstream out(folder + "/" + name, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::cerr << "ewaview-docs: cannot write " << folder << "/" << name << "\n";
      return 1;
    }
  }
  return 0;
}
