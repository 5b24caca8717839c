// Base of the filament energy terms: the layout they read (held by reference: the network
// rebuilds it in place) and their name; all act on the owner "filaments".
#pragma once

#include <string>

#include "filament/filament_layout.hpp"
#include "mech/energy_term.hpp"

namespace cortex {

class FilamentTerm : public EnergyTerm {
 public:
  FilamentTerm(const FilamentLayout& layout, std::string name) : layout_(layout), name_(std::move(name)) {}
  const std::string& name() const override { return name_; }
  const std::string& owner() const override {
    static const std::string kOwner = "filaments";
    return kOwner;
  }

 protected:
  const FilamentLayout& layout_;

 private:
  std::string name_;
};

}  // namespace cortex
