# Figure rules, included by the top-level Makefile (which defines OUT, BIN, PY
# and FIGS before the include). One rule for every driver's data set, one per
# figure.
#
# A driver <drv> named in DRIVERS runs as $(BIN)/<drv> --out $(OUT): it
# writes $(OUT)/data/<drv>/ and $(OUT)/claims/; the stamp
# $(OUT)/data/<drv>/.done is touched only after it succeeds, so a failed run
# is retried next time (drivers write every file atomically (CsvWriter), so a
# failure never leaves half a CSV). The report is re-made when a driver
# re-ran, even a driver with no figure (the Makefile's
# $(wildcard $(OUT)/claims/*.csv) is expanded before the drivers run, so it
# misses claim files created in the same run). Their rules stand at the end,
# once DRIVERS is complete.
DRIVERS :=

# $(call figure,<png>,<script>,<drv>,<helpers>) draws $(OUT)/figures/<png>.png
# with figures/<script>.py from <drv>'s data; <helpers> names the modules
# figures/<helper>_common.py the script imports (a change to one re-draws it):
#
#   $(OUT)/figures/<png>.png: $(OUT)/data/<drv>/.done figures/<script>.py figures/<helper>_common.py ...
#   	$(PY) figures/<script>.py $(OUT)/data/<drv> $@
#   FIGS += $(OUT)/figures/<png>.png
#   DRIVERS += <drv>
#
# A new driver takes one such line per figure, or DRIVERS += <drv> alone when
# it has no figure. Figures whose script takes more arguments have their rules
# written out (collapse, S1).
define figure_rules
$(OUT)/figures/$(1).png: $(OUT)/data/$(3)/.done figures/$(2).py $(patsubst %,figures/%_common.py,$(4))
	$(PY) figures/$(2).py $(OUT)/data/$(3) $$@
FIGS += $(OUT)/figures/$(1).png
DRIVERS += $(3)
endef
figure = $(eval $(call figure_rules,$(1),$(2),$(3),$(4)))

# --- Paper A Sects. 3.1.2, 3.2.1: entrance block, force as energy gradient ---
$(call figure,fig_contact_statements,fig_contact_statements,contact_statements,potential paper)

# --- Paper A Sect. 3.1.3: intersection polygon against CGAL (no figure) -------
# (the program lives in property_tests/, the only directory that links CGAL)
$(OUT)/data/exact_geometry/.done: $(BIN)/geometry_claims
	$(BIN)/geometry_claims --out $(OUT)
	@mkdir -p $(@D) && touch $@
$(OUT)/report.md: $(OUT)/data/exact_geometry/.done

# --- Paper A Sect. 3.2.2: potential fields, Figs. 4b and 5 -------------------
$(call figure,fig04b_potential,fig04_potential,potential_fields,potential)
$(call figure,fig05_potential,fig05_potential,potential_fields,potential)

# --- Paper A Sect. 4.1: two squares, Fig. 8 ----------------------------------
$(call figure,fig08_two_squares,fig08_two_squares,two_squares,potential paper)

# --- Paper A Sect. 4.2: symmetric stack, Fig. 10 -----------------------------
$(call figure,fig10_symmetric_stack,fig10_symmetric_stack,symmetric_stack,potential paper)

# --- Paper A Sect. 4.3: incline, Fig. 12 --------------------------------------
$(call figure,fig12_incline,fig12_incline,incline,potential paper)

# --- Paper A Sect. 3.2.2: Fig. 4a, previous sub-polygon potential (reconstructed) --
$(call figure,fig04a_previous_potential,fig04a_previous_potential,previous_potential,potential)

# --- Paper A Sect. 5.1: bouncing block, Fig. 14 --------------------------------
$(call figure,fig14_bouncing_block,fig14_bouncing_block,bouncing_block,potential paper)

# --- Paper A Sect. 5.2: small-angle triangles, Fig. 16 -------------------------
$(call figure,fig16_small_angles,fig16_small_angles,small_angles,potential paper)

# --- Paper A Sect. 5.3: small edges, Fig. 18 -----------------------------------
$(call figure,fig18_small_edges,fig18_small_edges,small_edges,potential paper)

# --- Beyond Sect. 5: extreme geometry, dt / dt_crit against the sizes ---------
$(call figure,extreme_geometry,fig_extreme_geometry,extreme_geometry,potential paper)

# --- Beyond Sect. 3.2.3: is the paper's segmentation exact? --------------------
$(call figure,segmentation_study,fig_segmentation_study,segmentation,potential paper)

# --- Paper B Sect. 6: two prisms, two-scale contact, Figs. 13-16 -------------
$(call figure,figB13_15_prisms,figB13_15_prisms,B_6_two_prisms,cdem potential)
$(call figure,figB16_displacement,figB16_displacement,B_6_two_prisms,cdem potential paper)

# --- Paper A vs Paper B contact on the same collisions (dt sweeps) -----------
$(call figure,figB_comparison,figB_comparison,B_7_contact_comparison,cdem potential paper)

# --- Beyond both papers: two elastic bars against 1D wave theory (B, B0, A) ---
$(call figure,figB_bar_waves,figB_bar_waves,B_8_bar_waves,cdem potential paper)

# --- Beyond Paper B: impact study of the two-scale contact (oblique impacts) ---
$(call figure,figB_impact_study,figB_impact_study,B_9_impact_study,cdem potential)

# --- Paper A Sect. 6.1: collapse of a jointed rock column, Fig. 20 ----------
# ~75,000 steps per case (two cases): the longest driver; it prints progress.
$(call figure,fig20_collapse,fig20_collapse,collapse,blocks potential paper)

COLLAPSE_DEPS := $(OUT)/data/collapse/.done figures/blocks_common.py figures/potential_common.py
$(OUT)/figures/fig20_collapse_runout.png: $(COLLAPSE_DEPS) figures/fig20_collapse.py figures/paper_common.py
	$(PY) figures/fig20_collapse.py --runout $(OUT)/data/collapse $@
$(OUT)/figures/anim_collapse_case%.gif: $(COLLAPSE_DEPS) figures/anim_collapse.py
	$(PY) figures/anim_collapse.py $(OUT)/data/collapse case$* $@

FIGS += $(OUT)/figures/fig20_collapse_runout.png \
        $(OUT)/figures/anim_collapse_case1.gif $(OUT)/figures/anim_collapse_case2.gif

# --- Paper A Sect. 6.2: toppling and slumping valley slopes, Fig. 22 --------
$(call figure,fig22_toppling,fig22_toppling,toppling_slumping,blocks potential paper)

# --- S1: work precision, error against run time --------------------------
# One figure per study case; the case is the script's third argument.
DRIVERS += work_precision
S1_CASES := figS1a_two_squares:4.1 figS1b_incline:4.3 figS1c_resting_block:resting figS1d_triangles:5.2 \
            figS1e_bouncing_block:5.1 figS1f_small_edge:5.3 figS1g_free_rotation:free figS1h_damped_flight:damped
S1_FIGS := $(foreach c,$(S1_CASES),$(OUT)/figures/$(word 1,$(subst :, ,$(c))).png)
$(S1_FIGS): $(OUT)/figures/%.png: $(OUT)/data/work_precision/.done figures/figS1_work_precision.py figures/potential_common.py
	$(PY) figures/figS1_work_precision.py $(OUT)/data/work_precision $@ $(word 2,$(subst :, ,$(filter $*:%,$(S1_CASES))))

FIGS += $(S1_FIGS)

# --- S2: stability maps (kn x dt) and the dt_crit check ---------------------
$(call figure,figS2_stability_maps,figS2_stability_maps,stability_maps,potential paper)

# --- S3: extreme cases (table in the report; no figure) ---------------------
DRIVERS += extreme_cases

# --- S3: penetration map (guard on and off over speed, kn and dt) ------------
$(call figure,figS3_penetration_map,figS3_penetration_map,penetration_map,potential paper)

# --- Every driver's run (DRIVERS is complete here) ---------------------------
DRIVER_STAMPS := $(patsubst %,$(OUT)/data/%/.done,$(sort $(DRIVERS)))
$(DRIVER_STAMPS): $(OUT)/data/%/.done: $(BIN)/%
	$(BIN)/$* --out $(OUT)
	@touch $@
$(OUT)/report.md: $(DRIVER_STAMPS)
