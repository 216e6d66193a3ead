// SPDX-License-Identifier: Apache-2.0
// Object classification of the application layer (thesis 5.3.3): its parts, one job a header,
// in one include for code that uses several of them.
#pragma once

#include "host/app/classifiers.hpp"      // parallelepiped, SVM, network; their training
#include "host/app/classify_rates.hpp"   // Table 5.6's rates of a classifier on rows
#include "host/app/feature_csv.hpp"      // feature rows as CSV
#include "host/app/model_file.hpp"       // load_classifier (Classifier::save writes the file)
#include "host/app/object_features.hpp"  // the five features, the three classes, Table 5.4
#include "host/app/table54_sampler.hpp"  // synthetic rows drawn from Table 5.4
