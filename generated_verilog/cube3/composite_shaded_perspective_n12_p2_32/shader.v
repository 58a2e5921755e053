module top$pipeline$shade$0(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b0;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b1;
    localparam  edge_transparent = 1'b1;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0;
    wire  normal$q_neg$1;
    wire  normal$q_neg$2;
    wire  [6:0] normal$q_mag$0;
    wire  [6:0] normal$q_mag$1;
    wire  [6:0] normal$q_mag$2;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse;
    wire  [15:0] lighting$specular;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$pipeline$shade$0$lut lut(
        .clock(lut$clock),
        .host_write(lut$host_write),
        .host_address(lut$host_address),
        .host_data(lut$host_data),
        .address(lut$address),
        .data(lut$data)
    );
    top$pipeline$shade$0$normal normal(
        .clock(normal$clock),
        .neg$0(normal$neg$0),
        .neg$1(normal$neg$1),
        .neg$2(normal$neg$2),
        .mag$0(normal$mag$0),
        .mag$1(normal$mag$1),
        .mag$2(normal$mag$2),
        .q_neg$0(normal$q_neg$0),
        .q_neg$1(normal$q_neg$1),
        .q_neg$2(normal$q_neg$2),
        .q_mag$0(normal$q_mag$0),
        .q_mag$1(normal$q_mag$1),
        .q_mag$2(normal$q_mag$2)
    );
    top$pipeline$shade$0$lighting lighting(
        .clock(lighting$clock),
        .host_write(lighting$host_write),
        .host_address(lighting$host_address),
        .host_data(lighting$host_data),
        .q_neg$0(lighting$q_neg$0),
        .q_neg$1(lighting$q_neg$1),
        .q_neg$2(lighting$q_neg$2),
        .q_mag$0(lighting$q_mag$0),
        .q_mag$1(lighting$q_mag$1),
        .q_mag$2(lighting$q_mag$2),
        .diffuse(lighting$diffuse),
        .specular(lighting$specular)
    );
    top$pipeline$shade$0$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$pipeline$shade$0$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$pipeline$shade$0$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$pipeline$shade$0$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$pipeline$shade$0$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$pipeline$shade$0$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$pipeline$shade$0$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$pipeline$shade$0$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$pipeline$shade$0$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$pipeline$shade$0$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$pipeline$shade$0$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$pipeline$shade$0$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$pipeline$shade$0$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$pipeline$shade$0$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$pipeline$shade$0$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$pipeline$shade$0$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$pipeline$shade$0$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$pipeline$shade$0$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$pipeline$shade$0$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$pipeline$shade$0$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$pipeline$shade$0$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$pipeline$shade$0$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$pipeline$shade$0$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$pipeline$shade$0$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$pipeline$shade$0$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$pipeline$shade$0$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$pipeline$shade$0$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$pipeline$shade$0$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$pipeline$shade$0$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$pipeline$shade$0$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$pipeline$shade$0$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$pipeline$shade$0$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$pipeline$shade$0$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$pipeline$shade$0$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$pipeline$shade$0$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$pipeline$shade$0$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$pipeline$shade$0$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$pipeline$shade$0$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$pipeline$shade$0$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$pipeline$shade$0$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$pipeline$shade$0$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$pipeline$shade$0$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$pipeline$shade$0$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$pipeline$shade$0$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$pipeline$shade$0$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$pipeline$shade$0$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$pipeline$shade$0$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$pipeline$shade$0$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$pipeline$shade$0$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$pipeline$shade$0$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$pipeline$shade$0$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$pipeline$shade$0$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$pipeline$shade$0$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$pipeline$shade$0$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$pipeline$shade$0$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$pipeline$shade$0$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$pipeline$shade$0$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$pipeline$shade$0$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$pipeline$shade$0$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$pipeline$shade$0$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$pipeline$shade$0$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$pipeline$shade$0$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$pipeline$shade$0$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$pipeline$shade$0$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$pipeline$shade$0$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$pipeline$shade$0$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$pipeline$shade$0$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$pipeline$shade$0$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$pipeline$shade$0$lit_r lit_r(
        .clock(lit_r$clock),
        .a(lit_r$a),
        .b(lit_r$b),
        .c(lit_r$c),
        .y(lit_r$y)
    );
    top$pipeline$shade$0$lit_g lit_g(
        .clock(lit_g$clock),
        .a(lit_g$a),
        .b(lit_g$b),
        .c(lit_g$c),
        .y(lit_g$y)
    );
    top$pipeline$shade$0$lit_b lit_b(
        .clock(lit_b$clock),
        .a(lit_b$a),
        .b(lit_b$b),
        .c(lit_b$c),
        .y(lit_b$y)
    );
    top$pipeline$shade$0$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$pipeline$shade$0$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$pipeline$shade$0$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$pipeline$shade$0$mul_r mul_r(
        .clock(mul_r$clock),
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$pipeline$shade$0$mul_g mul_g(
        .clock(mul_g$clock),
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$pipeline$shade$0$mul_b mul_b(
        .clock(mul_b$clock),
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$pipeline$shade$0$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$pipeline$shade$0$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$pipeline$shade$0$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$pipeline$shade$0$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$pipeline$shade$0
module top$pipeline$shade$0$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$a_q
module top$pipeline$shade$0$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$0
module top$pipeline$shade$0$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$1
module top$pipeline$shade$0$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$10
module top$pipeline$shade$0$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$2
module top$pipeline$shade$0$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$3
module top$pipeline$shade$0$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$4
module top$pipeline$shade$0$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$5
module top$pipeline$shade$0$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$6
module top$pipeline$shade$0$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$7
module top$pipeline$shade$0$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$8
module top$pipeline$shade$0$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$alpha_q$9
module top$pipeline$shade$0$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$b_q
module top$pipeline$shade$0$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$g_q
module top$pipeline$shade$0$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$gate_q$0
module top$pipeline$shade$0$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$gate_q$1
module top$pipeline$shade$0$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$gate_q$2
module top$pipeline$shade$0$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$gate_q$3
module top$pipeline$shade$0$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$gate_q$4
module top$pipeline$shade$0$lighting(clock,host_write,host_address,host_data,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2,diffuse,specular);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  q_neg$0;
    input wire  q_neg$1;
    input wire  q_neg$2;
    input wire  [6:0] q_mag$0;
    input wire  [6:0] q_mag$1;
    input wire  [6:0] q_mag$2;
    output reg  [15:0] diffuse;
    output reg  [15:0] specular;
    
    // Constant declarations
    localparam  saturation = 'hffff;
    localparam  wide_dot = 1'b0;
    localparam  half_ulp = 64'h2000000;
    localparam  shift = 8'h1a;
    localparam  last = 10'b1111111111;
    localparam  sat_t = 64'h4008021;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    reg  [15:0] rnorm$address;
    wire  [15:0] rnorm$data;
    reg  [6:0] square$0$address;
    wire  [15:0] square$0$data;
    reg  [6:0] square$1$address;
    wire  [15:0] square$1$data;
    reg  [6:0] square$2$address;
    wire  [15:0] square$2$data;
    reg  diffuse_table$clock;
    reg  diffuse_table$host_write;
    reg  [23:0] diffuse_table$host_address;
    reg  [63:0] diffuse_table$host_data;
    reg  [9:0] diffuse_table$address;
    wire  [15:0] diffuse_table$data;
    reg  specular_table$clock;
    reg  specular_table$host_write;
    reg  [23:0] specular_table$host_address;
    reg  [63:0] specular_table$host_data;
    reg  [9:0] specular_table$address;
    wire  [15:0] specular_table$data;
    reg  [15:0] ml_q$0$d;
    wire  [15:0] ml_q$0$q;
    reg  ml_q$0$clock;
    reg  [15:0] ml_q$1$d;
    wire  [15:0] ml_q$1$q;
    reg  ml_q$1$clock;
    reg  [15:0] ml_q$2$d;
    wire  [15:0] ml_q$2$q;
    reg  ml_q$2$clock;
    reg  [15:0] mh_q$0$d;
    wire  [15:0] mh_q$0$q;
    reg  mh_q$0$clock;
    reg  [15:0] mh_q$1$d;
    wire  [15:0] mh_q$1$q;
    reg  mh_q$1$clock;
    reg  [15:0] mh_q$2$d;
    wire  [15:0] mh_q$2$q;
    reg  mh_q$2$clock;
    reg  p_l$0$clock;
    reg  [15:0] p_l$0$a;
    reg  [15:0] p_l$0$b;
    wire  [31:0] p_l$0$p;
    reg  p_l$1$clock;
    reg  [15:0] p_l$1$a;
    reg  [15:0] p_l$1$b;
    wire  [31:0] p_l$1$p;
    reg  p_l$2$clock;
    reg  [15:0] p_l$2$a;
    reg  [15:0] p_l$2$b;
    wire  [31:0] p_l$2$p;
    reg  p_h$0$clock;
    reg  [15:0] p_h$0$a;
    reg  [15:0] p_h$0$b;
    wire  [31:0] p_h$0$p;
    reg  p_h$1$clock;
    reg  [15:0] p_h$1$a;
    reg  [15:0] p_h$1$b;
    wire  [31:0] p_h$1$p;
    reg  p_h$2$clock;
    reg  [15:0] p_h$2$a;
    reg  [15:0] p_h$2$b;
    wire  [31:0] p_h$2$p;
    reg  sl_q$0$d;
    wire  sl_q$0$q;
    reg  sl_q$0$clock;
    reg  sl_q$1$d;
    wire  sl_q$1$q;
    reg  sl_q$1$clock;
    reg  sl_q$2$d;
    wire  sl_q$2$q;
    reg  sl_q$2$clock;
    reg  sh_q$0$d;
    wire  sh_q$0$q;
    reg  sh_q$0$clock;
    reg  sh_q$1$d;
    wire  sh_q$1$q;
    reg  sh_q$1$clock;
    reg  sh_q$2$d;
    wire  sh_q$2$q;
    reg  sh_q$2$clock;
    reg  [15:0] n2_q$d;
    wire  [15:0] n2_q$q;
    reg  n2_q$clock;
    reg  [31:0] pair_l$d;
    wire  [31:0] pair_l$q;
    reg  pair_l$clock;
    reg  [31:0] pair_h$d;
    wire  [31:0] pair_h$q;
    reg  pair_h$clock;
    reg  [31:0] third_l$d;
    wire  [31:0] third_l$q;
    reg  third_l$clock;
    reg  [31:0] third_h$d;
    wire  [31:0] third_h$q;
    reg  third_h$clock;
    reg  [15:0] rn$d;
    wire  [15:0] rn$q;
    reg  rn$clock;
    reg  [31:0] d_l$d;
    wire  [31:0] d_l$q;
    reg  d_l$clock;
    reg  [31:0] d_h$d;
    wire  [31:0] d_h$q;
    reg  d_h$clock;
    reg  [15:0] rn_3$d;
    wire  [15:0] rn_3$q;
    reg  rn_3$clock;
    reg  lit_3$d;
    wire  lit_3$q;
    reg  lit_3$clock;
    reg  t_l$clock;
    reg  [15:0] t_l$a;
    reg  [15:0] t_l$b;
    wire  [31:0] t_l$p;
    reg  t_h$clock;
    reg  [15:0] t_h$a;
    reg  [15:0] t_h$b;
    wire  [31:0] t_h$p;
    reg  u_l$clock;
    reg  [15:0] u_l$a;
    reg  [15:0] u_l$b;
    wire  [31:0] u_l$p;
    reg  u_h$clock;
    reg  [15:0] u_h$a;
    reg  [15:0] u_h$b;
    wire  [31:0] u_h$p;
    reg  lit_4$d;
    wire  lit_4$q;
    reg  lit_4$clock;
    reg  [9:0] idx_l$d;
    wire  [9:0] idx_l$q;
    reg  idx_l$clock;
    reg  [9:0] idx_h$d;
    wire  [9:0] idx_h$q;
    reg  idx_h$clock;
    reg  lit_5$d;
    wire  lit_5$q;
    reg  lit_5$clock;
    reg  lit_6$d;
    wire  lit_6$q;
    reg  lit_6$clock;
    reg  [15:0] diffuse_q$d;
    wire  [15:0] diffuse_q$q;
    reg  diffuse_q$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    
    // Local signals
    reg  [15:0] m_l$0;
    reg  [15:0] m_l$1;
    reg  [15:0] m_l$2;
    reg  [15:0] m_h$0;
    reg  [15:0] m_h$1;
    reg  [15:0] m_h$2;
    reg  [15:0] qm$0;
    reg  [15:0] qm$1;
    reg  [15:0] qm$2;
    reg  [31:0] t_pl$0;
    reg  [31:0] t_pl$1;
    reg  [31:0] t_pl$2;
    reg  [31:0] t_ph$0;
    reg  [31:0] t_ph$1;
    reg  [31:0] t_ph$2;
    reg  [31:0] c_l;
    reg  [31:0] c_h;
    reg  [15:0] n2;
    reg  [31:0] dot_l;
    reg  [31:0] dot_h;
    reg  [63:0] tt_l;
    reg  [63:0] tt_h;
    reg  [9:0] i_l;
    reg  [9:0] i_h;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1)
    );
    top$pipeline$shade$0$lighting$rnorm rnorm(
        .address(rnorm$address),
        .data(rnorm$data)
    );
    top$pipeline$shade$0$lighting$square$0 square$0(
        .address(square$0$address),
        .data(square$0$data)
    );
    top$pipeline$shade$0$lighting$square$1 square$1(
        .address(square$1$address),
        .data(square$1$data)
    );
    top$pipeline$shade$0$lighting$square$2 square$2(
        .address(square$2$address),
        .data(square$2$data)
    );
    top$pipeline$shade$0$lighting$diffuse_table diffuse_table(
        .clock(diffuse_table$clock),
        .host_write(diffuse_table$host_write),
        .host_address(diffuse_table$host_address),
        .host_data(diffuse_table$host_data),
        .address(diffuse_table$address),
        .data(diffuse_table$data)
    );
    top$pipeline$shade$0$lighting$specular_table specular_table(
        .clock(specular_table$clock),
        .host_write(specular_table$host_write),
        .host_address(specular_table$host_address),
        .host_data(specular_table$host_data),
        .address(specular_table$address),
        .data(specular_table$data)
    );
    top$pipeline$shade$0$lighting$ml_q$0 ml_q$0(
        .d(ml_q$0$d),
        .q(ml_q$0$q),
        .clock(ml_q$0$clock)
    );
    top$pipeline$shade$0$lighting$ml_q$1 ml_q$1(
        .d(ml_q$1$d),
        .q(ml_q$1$q),
        .clock(ml_q$1$clock)
    );
    top$pipeline$shade$0$lighting$ml_q$2 ml_q$2(
        .d(ml_q$2$d),
        .q(ml_q$2$q),
        .clock(ml_q$2$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$0 mh_q$0(
        .d(mh_q$0$d),
        .q(mh_q$0$q),
        .clock(mh_q$0$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$1 mh_q$1(
        .d(mh_q$1$d),
        .q(mh_q$1$q),
        .clock(mh_q$1$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$2 mh_q$2(
        .d(mh_q$2$d),
        .q(mh_q$2$q),
        .clock(mh_q$2$clock)
    );
    top$pipeline$shade$0$lighting$p_l$0 p_l$0(
        .clock(p_l$0$clock),
        .a(p_l$0$a),
        .b(p_l$0$b),
        .p(p_l$0$p)
    );
    top$pipeline$shade$0$lighting$p_l$1 p_l$1(
        .clock(p_l$1$clock),
        .a(p_l$1$a),
        .b(p_l$1$b),
        .p(p_l$1$p)
    );
    top$pipeline$shade$0$lighting$p_l$2 p_l$2(
        .clock(p_l$2$clock),
        .a(p_l$2$a),
        .b(p_l$2$b),
        .p(p_l$2$p)
    );
    top$pipeline$shade$0$lighting$p_h$0 p_h$0(
        .clock(p_h$0$clock),
        .a(p_h$0$a),
        .b(p_h$0$b),
        .p(p_h$0$p)
    );
    top$pipeline$shade$0$lighting$p_h$1 p_h$1(
        .clock(p_h$1$clock),
        .a(p_h$1$a),
        .b(p_h$1$b),
        .p(p_h$1$p)
    );
    top$pipeline$shade$0$lighting$p_h$2 p_h$2(
        .clock(p_h$2$clock),
        .a(p_h$2$a),
        .b(p_h$2$b),
        .p(p_h$2$p)
    );
    top$pipeline$shade$0$lighting$sl_q$0 sl_q$0(
        .d(sl_q$0$d),
        .q(sl_q$0$q),
        .clock(sl_q$0$clock)
    );
    top$pipeline$shade$0$lighting$sl_q$1 sl_q$1(
        .d(sl_q$1$d),
        .q(sl_q$1$q),
        .clock(sl_q$1$clock)
    );
    top$pipeline$shade$0$lighting$sl_q$2 sl_q$2(
        .d(sl_q$2$d),
        .q(sl_q$2$q),
        .clock(sl_q$2$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$0 sh_q$0(
        .d(sh_q$0$d),
        .q(sh_q$0$q),
        .clock(sh_q$0$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$1 sh_q$1(
        .d(sh_q$1$d),
        .q(sh_q$1$q),
        .clock(sh_q$1$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$2 sh_q$2(
        .d(sh_q$2$d),
        .q(sh_q$2$q),
        .clock(sh_q$2$clock)
    );
    top$pipeline$shade$0$lighting$n2_q n2_q(
        .d(n2_q$d),
        .q(n2_q$q),
        .clock(n2_q$clock)
    );
    top$pipeline$shade$0$lighting$pair_l pair_l(
        .d(pair_l$d),
        .q(pair_l$q),
        .clock(pair_l$clock)
    );
    top$pipeline$shade$0$lighting$pair_h pair_h(
        .d(pair_h$d),
        .q(pair_h$q),
        .clock(pair_h$clock)
    );
    top$pipeline$shade$0$lighting$third_l third_l(
        .d(third_l$d),
        .q(third_l$q),
        .clock(third_l$clock)
    );
    top$pipeline$shade$0$lighting$third_h third_h(
        .d(third_h$d),
        .q(third_h$q),
        .clock(third_h$clock)
    );
    top$pipeline$shade$0$lighting$rn rn(
        .d(rn$d),
        .q(rn$q),
        .clock(rn$clock)
    );
    top$pipeline$shade$0$lighting$d_l d_l(
        .d(d_l$d),
        .q(d_l$q),
        .clock(d_l$clock)
    );
    top$pipeline$shade$0$lighting$d_h d_h(
        .d(d_h$d),
        .q(d_h$q),
        .clock(d_h$clock)
    );
    top$pipeline$shade$0$lighting$rn_3 rn_3(
        .d(rn_3$d),
        .q(rn_3$q),
        .clock(rn_3$clock)
    );
    top$pipeline$shade$0$lighting$lit_3 lit_3(
        .d(lit_3$d),
        .q(lit_3$q),
        .clock(lit_3$clock)
    );
    top$pipeline$shade$0$lighting$t_l t_l(
        .clock(t_l$clock),
        .a(t_l$a),
        .b(t_l$b),
        .p(t_l$p)
    );
    top$pipeline$shade$0$lighting$t_h t_h(
        .clock(t_h$clock),
        .a(t_h$a),
        .b(t_h$b),
        .p(t_h$p)
    );
    top$pipeline$shade$0$lighting$u_l u_l(
        .clock(u_l$clock),
        .a(u_l$a),
        .b(u_l$b),
        .p(u_l$p)
    );
    top$pipeline$shade$0$lighting$u_h u_h(
        .clock(u_h$clock),
        .a(u_h$a),
        .b(u_h$b),
        .p(u_h$p)
    );
    top$pipeline$shade$0$lighting$lit_4 lit_4(
        .d(lit_4$d),
        .q(lit_4$q),
        .clock(lit_4$clock)
    );
    top$pipeline$shade$0$lighting$idx_l idx_l(
        .d(idx_l$d),
        .q(idx_l$q),
        .clock(idx_l$clock)
    );
    top$pipeline$shade$0$lighting$idx_h idx_h(
        .d(idx_h$d),
        .q(idx_h$q),
        .clock(idx_h$clock)
    );
    top$pipeline$shade$0$lighting$lit_5 lit_5(
        .d(lit_5$d),
        .q(lit_5$q),
        .clock(lit_5$clock)
    );
    top$pipeline$shade$0$lighting$lit_6 lit_6(
        .d(lit_6$d),
        .q(lit_6$q),
        .clock(lit_6$clock)
    );
    top$pipeline$shade$0$lighting$diffuse_q diffuse_q(
        .d(diffuse_q$d),
        .q(diffuse_q$q),
        .clock(diffuse_q$clock)
    );
    top$pipeline$shade$0$lighting$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    
    // Update code
    always @(*) begin
        n2_q$clock = clock;
        pair_l$clock = clock;
        pair_h$clock = clock;
        third_l$clock = clock;
        third_h$clock = clock;
        rn$clock = clock;
        d_l$clock = clock;
        d_h$clock = clock;
        rn_3$clock = clock;
        lit_3$clock = clock;
        lit_4$clock = clock;
        idx_l$clock = clock;
        idx_h$clock = clock;
        lit_5$clock = clock;
        lit_6$clock = clock;
        diffuse_q$clock = clock;
        specular_q$clock = clock;
        n2_q$d = n2_q$q;
        pair_l$d = pair_l$q;
        pair_h$d = pair_h$q;
        third_l$d = third_l$q;
        third_h$d = third_h$q;
        rn$d = rn$q;
        d_l$d = d_l$q;
        d_h$d = d_h$q;
        rn_3$d = rn_3$q;
        lit_3$d = lit_3$q;
        lit_4$d = lit_4$q;
        idx_l$d = idx_l$q;
        idx_h$d = idx_h$q;
        lit_5$d = lit_5$q;
        lit_6$d = lit_6$q;
        diffuse_q$d = diffuse_q$q;
        specular_q$d = specular_q$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        diffuse_table$clock = clock;
        diffuse_table$host_write = host_write;
        diffuse_table$host_address = host_address;
        diffuse_table$host_data = host_data;
        specular_table$clock = clock;
        specular_table$host_write = host_write;
        specular_table$host_address = host_address;
        specular_table$host_data = host_data;
        qm$0 = 16'(q_mag$0);
        qm$1 = 16'(q_mag$1);
        qm$2 = 16'(q_mag$2);
        m_l$0 = regs$q$0[('h0)+:(16)];
        if (regs$q$0['hf]) begin
            m_l$0 = 'h0 - regs$q$0[('h0)+:(16)];
        end
        m_l$1 = regs$q$0[('h10)+:(16)];
        if (regs$q$0['h1f]) begin
            m_l$1 = 'h0 - regs$q$0[('h10)+:(16)];
        end
        m_l$2 = regs$q$0[('h20)+:(16)];
        if (regs$q$0['h2f]) begin
            m_l$2 = 'h0 - regs$q$0[('h20)+:(16)];
        end
        m_h$0 = regs$q$1[('h0)+:(16)];
        if (regs$q$1['hf]) begin
            m_h$0 = 'h0 - regs$q$1[('h0)+:(16)];
        end
        m_h$1 = regs$q$1[('h10)+:(16)];
        if (regs$q$1['h1f]) begin
            m_h$1 = 'h0 - regs$q$1[('h10)+:(16)];
        end
        m_h$2 = regs$q$1[('h20)+:(16)];
        if (regs$q$1['h2f]) begin
            m_h$2 = 'h0 - regs$q$1[('h20)+:(16)];
        end
        ml_q$0$clock = clock;
        mh_q$0$clock = clock;
        sl_q$0$clock = clock;
        sh_q$0$clock = clock;
        p_l$0$clock = clock;
        p_h$0$clock = clock;
        p_l$0$a = qm$0;
        p_h$0$a = qm$0;
        square$0$address = q_mag$0;
        ml_q$0$d = m_l$0;
        mh_q$0$d = m_h$0;
        p_l$0$b = ml_q$0$q;
        p_h$0$b = mh_q$0$q;
        ml_q$1$clock = clock;
        mh_q$1$clock = clock;
        sl_q$1$clock = clock;
        sh_q$1$clock = clock;
        p_l$1$clock = clock;
        p_h$1$clock = clock;
        p_l$1$a = qm$1;
        p_h$1$a = qm$1;
        square$1$address = q_mag$1;
        ml_q$1$d = m_l$1;
        mh_q$1$d = m_h$1;
        p_l$1$b = ml_q$1$q;
        p_h$1$b = mh_q$1$q;
        ml_q$2$clock = clock;
        mh_q$2$clock = clock;
        sl_q$2$clock = clock;
        sh_q$2$clock = clock;
        p_l$2$clock = clock;
        p_h$2$clock = clock;
        p_l$2$a = qm$2;
        p_h$2$a = qm$2;
        square$2$address = q_mag$2;
        ml_q$2$d = m_l$2;
        mh_q$2$d = m_h$2;
        p_l$2$b = ml_q$2$q;
        p_h$2$b = mh_q$2$q;
        sl_q$0$d = q_neg$0 ^ regs$q$0['hf];
        sl_q$1$d = q_neg$1 ^ regs$q$0['h1f];
        sl_q$2$d = q_neg$2 ^ regs$q$0['h2f];
        sh_q$0$d = q_neg$0 ^ regs$q$1['hf];
        sh_q$1$d = q_neg$1 ^ regs$q$1['h1f];
        sh_q$2$d = q_neg$2 ^ regs$q$1['h2f];
        n2 = square$0$data + square$1$data + square$2$data;
        n2_q$d = n2;
        t_pl$0 = p_l$0$p;
        if (sl_q$0$q) begin
            t_pl$0 = ~p_l$0$p;
        end
        t_ph$0 = p_h$0$p;
        if (sh_q$0$q) begin
            t_ph$0 = ~p_h$0$p;
        end
        t_pl$1 = p_l$1$p;
        if (sl_q$1$q) begin
            t_pl$1 = ~p_l$1$p;
        end
        t_ph$1 = p_h$1$p;
        if (sh_q$1$q) begin
            t_ph$1 = ~p_h$1$p;
        end
        t_pl$2 = p_l$2$p;
        if (sl_q$2$q) begin
            t_pl$2 = ~p_l$2$p;
        end
        t_ph$2 = p_h$2$p;
        if (sh_q$2$q) begin
            t_ph$2 = ~p_h$2$p;
        end
        c_l = 32'(sl_q$0$q) + 32'(sl_q$1$q) + 32'(sl_q$2$q);
        c_h = 32'(sh_q$0$q) + 32'(sh_q$1$q) + 32'(sh_q$2$q);
        pair_l$d = t_pl$0 + t_pl$1;
        pair_h$d = t_ph$0 + t_ph$1;
        third_l$d = t_pl$2 + c_l;
        third_h$d = t_ph$2 + c_h;
        rnorm$address = n2_q$q;
        rn$d = rnorm$data;
        dot_l = pair_l$q + third_l$q;
        dot_h = pair_h$q + third_h$q;
        d_l$d = dot_l & saturation;
        if (dot_l['h1f] | (dot_l == 'h0)) begin
            d_l$d = 'h0;
        end
        else if ((dot_l & ~saturation) != 'h0) begin
            d_l$d = saturation;
        end
        d_h$d = dot_h & saturation;
        if (dot_h['h1f] | (dot_h == 'h0)) begin
            d_h$d = 'h0;
        end
        else if ((dot_h & ~saturation) != 'h0) begin
            d_h$d = saturation;
        end
        rn_3$d = rn$q;
        lit_3$d = ~dot_l['h1f] & (dot_l != 'h0);
        t_l$clock = clock;
        t_h$clock = clock;
        u_l$clock = clock;
        u_h$clock = clock;
        t_l$a = d_l$q[('h0)+:(16)];
        t_h$a = d_h$q[('h0)+:(16)];
        u_l$a = d_l$q[('h10)+:(16)];
        u_h$a = d_h$q[('h10)+:(16)];
        t_l$b = rn_3$q;
        t_h$b = rn_3$q;
        u_l$b = rn_3$q;
        u_h$b = rn_3$q;
        lit_4$d = lit_3$q;
        tt_l = 64'(t_l$p);
        tt_h = 64'(t_h$p);
        if (wide_dot) begin
            tt_l = 64'(t_l$p) + (64'(u_l$p) << 'h10);
            tt_h = 64'(t_h$p) + (64'(u_h$p) << 'h10);
        end
        i_l = 10'(((tt_l << 'ha) - tt_l + half_ulp) >> shift);
        i_h = 10'(((tt_h << 'ha) - tt_h + half_ulp) >> shift);
        idx_l$d = i_l;
        if (tt_l >= sat_t) begin
            idx_l$d = last;
        end
        idx_h$d = i_h;
        if (tt_h >= sat_t) begin
            idx_h$d = last;
        end
        lit_5$d = lit_4$q;
        diffuse_table$address = idx_l$q;
        specular_table$address = idx_h$q;
        lit_6$d = lit_5$q;
        diffuse_q$d = diffuse_table$data;
        specular_q$d = 'h0;
        if (lit_6$q) begin
            specular_q$d = specular_table$data;
        end
        diffuse = diffuse_q$q;
        specular = specular_q$q;
    end
    
endmodule // top$pipeline$shade$0$lighting
module top$pipeline$shade$0$lighting$d_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$d_h
module top$pipeline$shade$0$lighting$d_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$d_l
module top$pipeline$shade$0$lighting$diffuse_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$diffuse_q
module top$pipeline$shade$0$lighting$diffuse_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h30000;
    localparam  window = 24'h30400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$diffuse_table$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lighting$diffuse_table
module top$pipeline$shade$0$lighting$diffuse_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lighting$diffuse_table$ram
module top$pipeline$shade$0$lighting$idx_h(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$idx_h
module top$pipeline$shade$0$lighting$idx_l(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$idx_l
module top$pipeline$shade$0$lighting$lit_3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$lit_3
module top$pipeline$shade$0$lighting$lit_4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$lit_4
module top$pipeline$shade$0$lighting$lit_5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$lit_5
module top$pipeline$shade$0$lighting$lit_6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$lit_6
module top$pipeline$shade$0$lighting$mh_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$mh_q$0
module top$pipeline$shade$0$lighting$mh_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$mh_q$1
module top$pipeline$shade$0$lighting$mh_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$mh_q$2
module top$pipeline$shade$0$lighting$ml_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$ml_q$0
module top$pipeline$shade$0$lighting$ml_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$ml_q$1
module top$pipeline$shade$0$lighting$ml_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$ml_q$2
module top$pipeline$shade$0$lighting$n2_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$n2_q
module top$pipeline$shade$0$lighting$p_h$0(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_h$0
module top$pipeline$shade$0$lighting$p_h$1(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_h$1
module top$pipeline$shade$0$lighting$p_h$2(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_h$2
module top$pipeline$shade$0$lighting$p_l$0(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_l$0
module top$pipeline$shade$0$lighting$p_l$1(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_l$1
module top$pipeline$shade$0$lighting$p_l$2(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$p_l$2
module top$pipeline$shade$0$lighting$pair_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$pair_h
module top$pipeline$shade$0$lighting$pair_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$pair_l
module top$pipeline$shade$0$lighting$regs(clock,host_write,host_address,host_data,q$0,q$1);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    
    // Constant declarations
    localparam  address$0 = 24'h10;
    localparam  address$1 = 24'h11;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$shade$0$lighting$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
    end
    
endmodule // top$pipeline$shade$0$lighting$regs
module top$pipeline$shade$0$lighting$regs$r$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$regs$r$0
module top$pipeline$shade$0$lighting$regs$r$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$regs$r$1
module top$pipeline$shade$0$lighting$rn(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$rn
module top$pipeline$shade$0$lighting$rn_3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$rn_3
module top$pipeline$shade$0$lighting$rnorm(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[9:0])
      10'd0: data = 16'h0;
      10'd1: data = 16'h8000;
      10'd2: data = 16'h5a82;
      10'd3: data = 16'h49e7;
      10'd4: data = 16'h4000;
      10'd5: data = 16'h393e;
      10'd6: data = 16'h3441;
      10'd7: data = 16'h3061;
      10'd8: data = 16'h2d41;
      10'd9: data = 16'h2aab;
      10'd10: data = 16'h287a;
      10'd11: data = 16'h2698;
      10'd12: data = 16'h24f3;
      10'd13: data = 16'h2380;
      10'd14: data = 16'h2236;
      10'd15: data = 16'h210d;
      10'd16: data = 16'h2000;
      10'd17: data = 16'h1f0b;
      10'd18: data = 16'h1e2b;
      10'd19: data = 16'h1d5d;
      10'd20: data = 16'h1c9f;
      10'd21: data = 16'h1bef;
      10'd22: data = 16'h1b4a;
      10'd23: data = 16'h1ab1;
      10'd24: data = 16'h1a21;
      10'd25: data = 16'h199a;
      10'd26: data = 16'h191a;
      10'd27: data = 16'h18a2;
      10'd28: data = 16'h1831;
      10'd29: data = 16'h17c5;
      10'd30: data = 16'h175f;
      10'd31: data = 16'h16fd;
      10'd32: data = 16'h16a1;
      10'd33: data = 16'h1648;
      10'd34: data = 16'h15f4;
      10'd35: data = 16'h15a3;
      10'd36: data = 16'h1555;
      10'd37: data = 16'h150b;
      10'd38: data = 16'h14c4;
      10'd39: data = 16'h147f;
      10'd40: data = 16'h143d;
      10'd41: data = 16'h13fe;
      10'd42: data = 16'h13c0;
      10'd43: data = 16'h1385;
      10'd44: data = 16'h134c;
      10'd45: data = 16'h1315;
      10'd46: data = 16'h12df;
      10'd47: data = 16'h12ac;
      10'd48: data = 16'h127a;
      10'd49: data = 16'h1249;
      10'd50: data = 16'h121a;
      10'd51: data = 16'h11ec;
      10'd52: data = 16'h11c0;
      10'd53: data = 16'h1195;
      10'd54: data = 16'h116b;
      10'd55: data = 16'h1142;
      10'd56: data = 16'h111b;
      10'd57: data = 16'h10f4;
      10'd58: data = 16'h10cf;
      10'd59: data = 16'h10aa;
      10'd60: data = 16'h1086;
      10'd61: data = 16'h1064;
      10'd62: data = 16'h1042;
      10'd63: data = 16'h1020;
      10'd64: data = 16'h1000;
      10'd65: data = 16'hfe0;
      10'd66: data = 16'hfc1;
      10'd67: data = 16'hfa3;
      10'd68: data = 16'hf86;
      10'd69: data = 16'hf69;
      10'd70: data = 16'hf4d;
      10'd71: data = 16'hf31;
      10'd72: data = 16'hf16;
      10'd73: data = 16'hefb;
      10'd74: data = 16'hee1;
      10'd75: data = 16'hec8;
      10'd76: data = 16'heaf;
      10'd77: data = 16'he96;
      10'd78: data = 16'he7e;
      10'd79: data = 16'he67;
      10'd80: data = 16'he50;
      10'd81: data = 16'he39;
      10'd82: data = 16'he23;
      10'd83: data = 16'he0d;
      10'd84: data = 16'hdf7;
      10'd85: data = 16'hde2;
      10'd86: data = 16'hdcd;
      10'd87: data = 16'hdb9;
      10'd88: data = 16'hda5;
      10'd89: data = 16'hd91;
      10'd90: data = 16'hd7e;
      10'd91: data = 16'hd6b;
      10'd92: data = 16'hd58;
      10'd93: data = 16'hd46;
      10'd94: data = 16'hd34;
      10'd95: data = 16'hd22;
      10'd96: data = 16'hd10;
      10'd97: data = 16'hcff;
      10'd98: data = 16'hcee;
      10'd99: data = 16'hcdd;
      10'd100: data = 16'hccd;
      10'd101: data = 16'hcbd;
      10'd102: data = 16'hcad;
      10'd103: data = 16'hc9d;
      10'd104: data = 16'hc8d;
      10'd105: data = 16'hc7e;
      10'd106: data = 16'hc6f;
      10'd107: data = 16'hc60;
      10'd108: data = 16'hc51;
      10'd109: data = 16'hc43;
      10'd110: data = 16'hc34;
      10'd111: data = 16'hc26;
      10'd112: data = 16'hc18;
      10'd113: data = 16'hc0b;
      10'd114: data = 16'hbfd;
      10'd115: data = 16'hbf0;
      10'd116: data = 16'hbe2;
      10'd117: data = 16'hbd5;
      10'd118: data = 16'hbc9;
      10'd119: data = 16'hbbc;
      10'd120: data = 16'hbaf;
      10'd121: data = 16'hba3;
      10'd122: data = 16'hb97;
      10'd123: data = 16'hb8b;
      10'd124: data = 16'hb7f;
      10'd125: data = 16'hb73;
      10'd126: data = 16'hb67;
      10'd127: data = 16'hb5c;
      10'd128: data = 16'hb50;
      10'd129: data = 16'hb45;
      10'd130: data = 16'hb3a;
      10'd131: data = 16'hb2f;
      10'd132: data = 16'hb24;
      10'd133: data = 16'hb19;
      10'd134: data = 16'hb0f;
      10'd135: data = 16'hb04;
      10'd136: data = 16'hafa;
      10'd137: data = 16'haf0;
      10'd138: data = 16'hae5;
      10'd139: data = 16'hadb;
      10'd140: data = 16'had1;
      10'd141: data = 16'hac8;
      10'd142: data = 16'habe;
      10'd143: data = 16'hab4;
      10'd144: data = 16'haab;
      10'd145: data = 16'haa1;
      10'd146: data = 16'ha98;
      10'd147: data = 16'ha8f;
      10'd148: data = 16'ha86;
      10'd149: data = 16'ha7c;
      10'd150: data = 16'ha73;
      10'd151: data = 16'ha6b;
      10'd152: data = 16'ha62;
      10'd153: data = 16'ha59;
      10'd154: data = 16'ha51;
      10'd155: data = 16'ha48;
      10'd156: data = 16'ha40;
      10'd157: data = 16'ha37;
      10'd158: data = 16'ha2f;
      10'd159: data = 16'ha27;
      10'd160: data = 16'ha1f;
      10'd161: data = 16'ha16;
      10'd162: data = 16'ha0e;
      10'd163: data = 16'ha07;
      10'd164: data = 16'h9ff;
      10'd165: data = 16'h9f7;
      10'd166: data = 16'h9ef;
      10'd167: data = 16'h9e8;
      10'd168: data = 16'h9e0;
      10'd169: data = 16'h9d9;
      10'd170: data = 16'h9d1;
      10'd171: data = 16'h9ca;
      10'd172: data = 16'h9c3;
      10'd173: data = 16'h9bb;
      10'd174: data = 16'h9b4;
      10'd175: data = 16'h9ad;
      10'd176: data = 16'h9a6;
      10'd177: data = 16'h99f;
      10'd178: data = 16'h998;
      10'd179: data = 16'h991;
      10'd180: data = 16'h98a;
      10'd181: data = 16'h984;
      10'd182: data = 16'h97d;
      10'd183: data = 16'h976;
      10'd184: data = 16'h970;
      10'd185: data = 16'h969;
      10'd186: data = 16'h963;
      10'd187: data = 16'h95c;
      10'd188: data = 16'h956;
      10'd189: data = 16'h950;
      10'd190: data = 16'h949;
      10'd191: data = 16'h943;
      10'd192: data = 16'h93d;
      10'd193: data = 16'h937;
      10'd194: data = 16'h931;
      10'd195: data = 16'h92b;
      10'd196: data = 16'h925;
      10'd197: data = 16'h91f;
      10'd198: data = 16'h919;
      10'd199: data = 16'h913;
      10'd200: data = 16'h90d;
      10'd201: data = 16'h907;
      10'd202: data = 16'h902;
      10'd203: data = 16'h8fc;
      10'd204: data = 16'h8f6;
      10'd205: data = 16'h8f1;
      10'd206: data = 16'h8eb;
      10'd207: data = 16'h8e6;
      10'd208: data = 16'h8e0;
      10'd209: data = 16'h8db;
      10'd210: data = 16'h8d5;
      10'd211: data = 16'h8d0;
      10'd212: data = 16'h8cb;
      10'd213: data = 16'h8c5;
      10'd214: data = 16'h8c0;
      10'd215: data = 16'h8bb;
      10'd216: data = 16'h8b6;
      10'd217: data = 16'h8b0;
      10'd218: data = 16'h8ab;
      10'd219: data = 16'h8a6;
      10'd220: data = 16'h8a1;
      10'd221: data = 16'h89c;
      10'd222: data = 16'h897;
      10'd223: data = 16'h892;
      10'd224: data = 16'h88d;
      10'd225: data = 16'h889;
      10'd226: data = 16'h884;
      10'd227: data = 16'h87f;
      10'd228: data = 16'h87a;
      10'd229: data = 16'h875;
      10'd230: data = 16'h871;
      10'd231: data = 16'h86c;
      10'd232: data = 16'h867;
      10'd233: data = 16'h863;
      10'd234: data = 16'h85e;
      10'd235: data = 16'h85a;
      10'd236: data = 16'h855;
      10'd237: data = 16'h851;
      10'd238: data = 16'h84c;
      10'd239: data = 16'h848;
      10'd240: data = 16'h843;
      10'd241: data = 16'h83f;
      10'd242: data = 16'h83a;
      10'd243: data = 16'h836;
      10'd244: data = 16'h832;
      10'd245: data = 16'h82d;
      10'd246: data = 16'h829;
      10'd247: data = 16'h825;
      10'd248: data = 16'h821;
      10'd249: data = 16'h81d;
      10'd250: data = 16'h818;
      10'd251: data = 16'h814;
      10'd252: data = 16'h810;
      10'd253: data = 16'h80c;
      10'd254: data = 16'h808;
      10'd255: data = 16'h804;
      10'd256: data = 16'h800;
      10'd257: data = 16'h7fc;
      10'd258: data = 16'h7f8;
      10'd259: data = 16'h7f4;
      10'd260: data = 16'h7f0;
      10'd261: data = 16'h7ec;
      10'd262: data = 16'h7e8;
      10'd263: data = 16'h7e5;
      10'd264: data = 16'h7e1;
      10'd265: data = 16'h7dd;
      10'd266: data = 16'h7d9;
      10'd267: data = 16'h7d5;
      10'd268: data = 16'h7d2;
      10'd269: data = 16'h7ce;
      10'd270: data = 16'h7ca;
      10'd271: data = 16'h7c7;
      10'd272: data = 16'h7c3;
      10'd273: data = 16'h7bf;
      10'd274: data = 16'h7bc;
      10'd275: data = 16'h7b8;
      10'd276: data = 16'h7b4;
      10'd277: data = 16'h7b1;
      10'd278: data = 16'h7ad;
      10'd279: data = 16'h7aa;
      10'd280: data = 16'h7a6;
      10'd281: data = 16'h7a3;
      10'd282: data = 16'h79f;
      10'd283: data = 16'h79c;
      10'd284: data = 16'h798;
      10'd285: data = 16'h795;
      10'd286: data = 16'h792;
      10'd287: data = 16'h78e;
      10'd288: data = 16'h78b;
      10'd289: data = 16'h788;
      10'd290: data = 16'h784;
      10'd291: data = 16'h781;
      10'd292: data = 16'h77e;
      10'd293: data = 16'h77a;
      10'd294: data = 16'h777;
      10'd295: data = 16'h774;
      10'd296: data = 16'h771;
      10'd297: data = 16'h76d;
      10'd298: data = 16'h76a;
      10'd299: data = 16'h767;
      10'd300: data = 16'h764;
      10'd301: data = 16'h761;
      10'd302: data = 16'h75e;
      10'd303: data = 16'h75a;
      10'd304: data = 16'h757;
      10'd305: data = 16'h754;
      10'd306: data = 16'h751;
      10'd307: data = 16'h74e;
      10'd308: data = 16'h74b;
      10'd309: data = 16'h748;
      10'd310: data = 16'h745;
      10'd311: data = 16'h742;
      10'd312: data = 16'h73f;
      10'd313: data = 16'h73c;
      10'd314: data = 16'h739;
      10'd315: data = 16'h736;
      10'd316: data = 16'h733;
      10'd317: data = 16'h730;
      10'd318: data = 16'h72e;
      10'd319: data = 16'h72b;
      10'd320: data = 16'h728;
      10'd321: data = 16'h725;
      10'd322: data = 16'h722;
      10'd323: data = 16'h71f;
      10'd324: data = 16'h71c;
      10'd325: data = 16'h71a;
      10'd326: data = 16'h717;
      10'd327: data = 16'h714;
      10'd328: data = 16'h711;
      10'd329: data = 16'h70f;
      10'd330: data = 16'h70c;
      10'd331: data = 16'h709;
      10'd332: data = 16'h706;
      10'd333: data = 16'h704;
      10'd334: data = 16'h701;
      10'd335: data = 16'h6fe;
      10'd336: data = 16'h6fc;
      10'd337: data = 16'h6f9;
      10'd338: data = 16'h6f6;
      10'd339: data = 16'h6f4;
      10'd340: data = 16'h6f1;
      10'd341: data = 16'h6ee;
      10'd342: data = 16'h6ec;
      10'd343: data = 16'h6e9;
      10'd344: data = 16'h6e7;
      10'd345: data = 16'h6e4;
      10'd346: data = 16'h6e2;
      10'd347: data = 16'h6df;
      10'd348: data = 16'h6dd;
      10'd349: data = 16'h6da;
      10'd350: data = 16'h6d8;
      10'd351: data = 16'h6d5;
      10'd352: data = 16'h6d3;
      10'd353: data = 16'h6d0;
      10'd354: data = 16'h6ce;
      10'd355: data = 16'h6cb;
      10'd356: data = 16'h6c9;
      10'd357: data = 16'h6c6;
      10'd358: data = 16'h6c4;
      10'd359: data = 16'h6c1;
      10'd360: data = 16'h6bf;
      10'd361: data = 16'h6bd;
      10'd362: data = 16'h6ba;
      10'd363: data = 16'h6b8;
      10'd364: data = 16'h6b6;
      10'd365: data = 16'h6b3;
      10'd366: data = 16'h6b1;
      10'd367: data = 16'h6ae;
      10'd368: data = 16'h6ac;
      10'd369: data = 16'h6aa;
      10'd370: data = 16'h6a8;
      10'd371: data = 16'h6a5;
      10'd372: data = 16'h6a3;
      10'd373: data = 16'h6a1;
      10'd374: data = 16'h69e;
      10'd375: data = 16'h69c;
      10'd376: data = 16'h69a;
      10'd377: data = 16'h698;
      10'd378: data = 16'h695;
      10'd379: data = 16'h693;
      10'd380: data = 16'h691;
      10'd381: data = 16'h68f;
      10'd382: data = 16'h68d;
      10'd383: data = 16'h68a;
      10'd384: data = 16'h688;
      10'd385: data = 16'h686;
      10'd386: data = 16'h684;
      10'd387: data = 16'h682;
      10'd388: data = 16'h680;
      10'd389: data = 16'h67d;
      10'd390: data = 16'h67b;
      10'd391: data = 16'h679;
      10'd392: data = 16'h677;
      10'd393: data = 16'h675;
      10'd394: data = 16'h673;
      10'd395: data = 16'h671;
      10'd396: data = 16'h66f;
      10'd397: data = 16'h66d;
      10'd398: data = 16'h66b;
      10'd399: data = 16'h668;
      10'd400: data = 16'h666;
      10'd401: data = 16'h664;
      10'd402: data = 16'h662;
      10'd403: data = 16'h660;
      10'd404: data = 16'h65e;
      10'd405: data = 16'h65c;
      10'd406: data = 16'h65a;
      10'd407: data = 16'h658;
      10'd408: data = 16'h656;
      10'd409: data = 16'h654;
      10'd410: data = 16'h652;
      10'd411: data = 16'h650;
      10'd412: data = 16'h64e;
      10'd413: data = 16'h64c;
      10'd414: data = 16'h64a;
      10'd415: data = 16'h649;
      10'd416: data = 16'h647;
      10'd417: data = 16'h645;
      10'd418: data = 16'h643;
      10'd419: data = 16'h641;
      10'd420: data = 16'h63f;
      10'd421: data = 16'h63d;
      10'd422: data = 16'h63b;
      10'd423: data = 16'h639;
      10'd424: data = 16'h637;
      10'd425: data = 16'h635;
      10'd426: data = 16'h634;
      10'd427: data = 16'h632;
      10'd428: data = 16'h630;
      10'd429: data = 16'h62e;
      10'd430: data = 16'h62c;
      10'd431: data = 16'h62a;
      10'd432: data = 16'h629;
      10'd433: data = 16'h627;
      10'd434: data = 16'h625;
      10'd435: data = 16'h623;
      10'd436: data = 16'h621;
      10'd437: data = 16'h620;
      10'd438: data = 16'h61e;
      10'd439: data = 16'h61c;
      10'd440: data = 16'h61a;
      10'd441: data = 16'h618;
      10'd442: data = 16'h617;
      10'd443: data = 16'h615;
      10'd444: data = 16'h613;
      10'd445: data = 16'h611;
      10'd446: data = 16'h610;
      10'd447: data = 16'h60e;
      10'd448: data = 16'h60c;
      10'd449: data = 16'h60a;
      10'd450: data = 16'h609;
      10'd451: data = 16'h607;
      10'd452: data = 16'h605;
      10'd453: data = 16'h604;
      10'd454: data = 16'h602;
      10'd455: data = 16'h600;
      10'd456: data = 16'h5ff;
      10'd457: data = 16'h5fd;
      10'd458: data = 16'h5fb;
      10'd459: data = 16'h5f9;
      10'd460: data = 16'h5f8;
      10'd461: data = 16'h5f6;
      10'd462: data = 16'h5f5;
      10'd463: data = 16'h5f3;
      10'd464: data = 16'h5f1;
      10'd465: data = 16'h5f0;
      10'd466: data = 16'h5ee;
      10'd467: data = 16'h5ec;
      10'd468: data = 16'h5eb;
      10'd469: data = 16'h5e9;
      10'd470: data = 16'h5e7;
      10'd471: data = 16'h5e6;
      10'd472: data = 16'h5e4;
      10'd473: data = 16'h5e3;
      10'd474: data = 16'h5e1;
      10'd475: data = 16'h5df;
      10'd476: data = 16'h5de;
      10'd477: data = 16'h5dc;
      10'd478: data = 16'h5db;
      10'd479: data = 16'h5d9;
      10'd480: data = 16'h5d8;
      10'd481: data = 16'h5d6;
      10'd482: data = 16'h5d5;
      10'd483: data = 16'h5d3;
      10'd484: data = 16'h5d1;
      10'd485: data = 16'h5d0;
      10'd486: data = 16'h5ce;
      10'd487: data = 16'h5cd;
      10'd488: data = 16'h5cb;
      10'd489: data = 16'h5ca;
      10'd490: data = 16'h5c8;
      10'd491: data = 16'h5c7;
      10'd492: data = 16'h5c5;
      10'd493: data = 16'h5c4;
      10'd494: data = 16'h5c2;
      10'd495: data = 16'h5c1;
      10'd496: data = 16'h5bf;
      10'd497: data = 16'h5be;
      10'd498: data = 16'h5bc;
      10'd499: data = 16'h5bb;
      10'd500: data = 16'h5b9;
      10'd501: data = 16'h5b8;
      10'd502: data = 16'h5b7;
      10'd503: data = 16'h5b5;
      10'd504: data = 16'h5b4;
      10'd505: data = 16'h5b2;
      10'd506: data = 16'h5b1;
      10'd507: data = 16'h5af;
      10'd508: data = 16'h5ae;
      10'd509: data = 16'h5ac;
      10'd510: data = 16'h5ab;
      10'd511: data = 16'h5aa;
      10'd512: data = 16'h5a8;
      10'd513: data = 16'h5a7;
      10'd514: data = 16'h5a5;
      10'd515: data = 16'h5a4;
      10'd516: data = 16'h5a3;
      10'd517: data = 16'h5a1;
      10'd518: data = 16'h5a0;
      10'd519: data = 16'h59e;
      10'd520: data = 16'h59d;
      10'd521: data = 16'h59c;
      10'd522: data = 16'h59a;
      10'd523: data = 16'h599;
      10'd524: data = 16'h597;
      10'd525: data = 16'h596;
      10'd526: data = 16'h595;
      10'd527: data = 16'h593;
      10'd528: data = 16'h592;
      10'd529: data = 16'h591;
      10'd530: data = 16'h58f;
      10'd531: data = 16'h58e;
      10'd532: data = 16'h58d;
      10'd533: data = 16'h58b;
      10'd534: data = 16'h58a;
      10'd535: data = 16'h589;
      10'd536: data = 16'h587;
      10'd537: data = 16'h586;
      10'd538: data = 16'h585;
      10'd539: data = 16'h583;
      10'd540: data = 16'h582;
      10'd541: data = 16'h581;
      10'd542: data = 16'h580;
      10'd543: data = 16'h57e;
      10'd544: data = 16'h57d;
      10'd545: data = 16'h57c;
      10'd546: data = 16'h57a;
      10'd547: data = 16'h579;
      10'd548: data = 16'h578;
      10'd549: data = 16'h577;
      10'd550: data = 16'h575;
      10'd551: data = 16'h574;
      10'd552: data = 16'h573;
      10'd553: data = 16'h571;
      10'd554: data = 16'h570;
      10'd555: data = 16'h56f;
      10'd556: data = 16'h56e;
      10'd557: data = 16'h56c;
      10'd558: data = 16'h56b;
      10'd559: data = 16'h56a;
      10'd560: data = 16'h569;
      10'd561: data = 16'h567;
      10'd562: data = 16'h566;
      10'd563: data = 16'h565;
      10'd564: data = 16'h564;
      10'd565: data = 16'h563;
      10'd566: data = 16'h561;
      10'd567: data = 16'h560;
      10'd568: data = 16'h55f;
      10'd569: data = 16'h55e;
      10'd570: data = 16'h55d;
      10'd571: data = 16'h55b;
      10'd572: data = 16'h55a;
      10'd573: data = 16'h559;
      10'd574: data = 16'h558;
      10'd575: data = 16'h557;
      10'd576: data = 16'h555;
      10'd577: data = 16'h554;
      10'd578: data = 16'h553;
      10'd579: data = 16'h552;
      10'd580: data = 16'h551;
      10'd581: data = 16'h54f;
      10'd582: data = 16'h54e;
      10'd583: data = 16'h54d;
      10'd584: data = 16'h54c;
      10'd585: data = 16'h54b;
      10'd586: data = 16'h54a;
      10'd587: data = 16'h548;
      10'd588: data = 16'h547;
      10'd589: data = 16'h546;
      10'd590: data = 16'h545;
      10'd591: data = 16'h544;
      10'd592: data = 16'h543;
      10'd593: data = 16'h542;
      10'd594: data = 16'h540;
      10'd595: data = 16'h53f;
      10'd596: data = 16'h53e;
      10'd597: data = 16'h53d;
      10'd598: data = 16'h53c;
      10'd599: data = 16'h53b;
      10'd600: data = 16'h53a;
      10'd601: data = 16'h539;
      10'd602: data = 16'h538;
      10'd603: data = 16'h536;
      10'd604: data = 16'h535;
      10'd605: data = 16'h534;
      10'd606: data = 16'h533;
      10'd607: data = 16'h532;
      10'd608: data = 16'h531;
      10'd609: data = 16'h530;
      10'd610: data = 16'h52f;
      10'd611: data = 16'h52e;
      10'd612: data = 16'h52d;
      10'd613: data = 16'h52b;
      10'd614: data = 16'h52a;
      10'd615: data = 16'h529;
      10'd616: data = 16'h528;
      10'd617: data = 16'h527;
      10'd618: data = 16'h526;
      10'd619: data = 16'h525;
      10'd620: data = 16'h524;
      10'd621: data = 16'h523;
      10'd622: data = 16'h522;
      10'd623: data = 16'h521;
      10'd624: data = 16'h520;
      10'd625: data = 16'h51f;
      10'd626: data = 16'h51e;
      10'd627: data = 16'h51d;
      10'd628: data = 16'h51c;
      10'd629: data = 16'h51b;
      10'd630: data = 16'h51a;
      10'd631: data = 16'h518;
      10'd632: data = 16'h517;
      10'd633: data = 16'h516;
      10'd634: data = 16'h515;
      10'd635: data = 16'h514;
      10'd636: data = 16'h513;
      10'd637: data = 16'h512;
      10'd638: data = 16'h511;
      10'd639: data = 16'h510;
      10'd640: data = 16'h50f;
      10'd641: data = 16'h50e;
      10'd642: data = 16'h50d;
      10'd643: data = 16'h50c;
      10'd644: data = 16'h50b;
      10'd645: data = 16'h50a;
      10'd646: data = 16'h509;
      10'd647: data = 16'h508;
      10'd648: data = 16'h507;
      10'd649: data = 16'h506;
      10'd650: data = 16'h505;
      10'd651: data = 16'h504;
      10'd652: data = 16'h503;
      10'd653: data = 16'h502;
      10'd654: data = 16'h501;
      10'd655: data = 16'h500;
      10'd656: data = 16'h4ff;
      10'd657: data = 16'h4fe;
      10'd658: data = 16'h4fd;
      10'd659: data = 16'h4fc;
      10'd660: data = 16'h4fb;
      10'd661: data = 16'h4fb;
      10'd662: data = 16'h4fa;
      10'd663: data = 16'h4f9;
      10'd664: data = 16'h4f8;
      10'd665: data = 16'h4f7;
      10'd666: data = 16'h4f6;
      10'd667: data = 16'h4f5;
      10'd668: data = 16'h4f4;
      10'd669: data = 16'h4f3;
      10'd670: data = 16'h4f2;
      10'd671: data = 16'h4f1;
      10'd672: data = 16'h4f0;
      10'd673: data = 16'h4ef;
      10'd674: data = 16'h4ee;
      10'd675: data = 16'h4ed;
      10'd676: data = 16'h4ec;
      10'd677: data = 16'h4eb;
      10'd678: data = 16'h4ea;
      10'd679: data = 16'h4ea;
      10'd680: data = 16'h4e9;
      10'd681: data = 16'h4e8;
      10'd682: data = 16'h4e7;
      10'd683: data = 16'h4e6;
      10'd684: data = 16'h4e5;
      10'd685: data = 16'h4e4;
      10'd686: data = 16'h4e3;
      10'd687: data = 16'h4e2;
      10'd688: data = 16'h4e1;
      10'd689: data = 16'h4e0;
      10'd690: data = 16'h4df;
      10'd691: data = 16'h4df;
      10'd692: data = 16'h4de;
      10'd693: data = 16'h4dd;
      10'd694: data = 16'h4dc;
      10'd695: data = 16'h4db;
      10'd696: data = 16'h4da;
      10'd697: data = 16'h4d9;
      10'd698: data = 16'h4d8;
      10'd699: data = 16'h4d7;
      10'd700: data = 16'h4d7;
      10'd701: data = 16'h4d6;
      10'd702: data = 16'h4d5;
      10'd703: data = 16'h4d4;
      10'd704: data = 16'h4d3;
      10'd705: data = 16'h4d2;
      10'd706: data = 16'h4d1;
      10'd707: data = 16'h4d0;
      10'd708: data = 16'h4cf;
      10'd709: data = 16'h4cf;
      10'd710: data = 16'h4ce;
      10'd711: data = 16'h4cd;
      10'd712: data = 16'h4cc;
      10'd713: data = 16'h4cb;
      10'd714: data = 16'h4ca;
      10'd715: data = 16'h4c9;
      10'd716: data = 16'h4c9;
      10'd717: data = 16'h4c8;
      10'd718: data = 16'h4c7;
      10'd719: data = 16'h4c6;
      10'd720: data = 16'h4c5;
      10'd721: data = 16'h4c4;
      10'd722: data = 16'h4c3;
      10'd723: data = 16'h4c3;
      10'd724: data = 16'h4c2;
      10'd725: data = 16'h4c1;
      10'd726: data = 16'h4c0;
      10'd727: data = 16'h4bf;
      10'd728: data = 16'h4be;
      10'd729: data = 16'h4be;
      10'd730: data = 16'h4bd;
      10'd731: data = 16'h4bc;
      10'd732: data = 16'h4bb;
      10'd733: data = 16'h4ba;
      10'd734: data = 16'h4b9;
      10'd735: data = 16'h4b9;
      10'd736: data = 16'h4b8;
      10'd737: data = 16'h4b7;
      10'd738: data = 16'h4b6;
      10'd739: data = 16'h4b5;
      10'd740: data = 16'h4b5;
      10'd741: data = 16'h4b4;
      10'd742: data = 16'h4b3;
      10'd743: data = 16'h4b2;
      10'd744: data = 16'h4b1;
      10'd745: data = 16'h4b1;
      10'd746: data = 16'h4b0;
      10'd747: data = 16'h4af;
      10'd748: data = 16'h4ae;
      10'd749: data = 16'h4ad;
      10'd750: data = 16'h4ad;
      10'd751: data = 16'h4ac;
      10'd752: data = 16'h4ab;
      10'd753: data = 16'h4aa;
      10'd754: data = 16'h4a9;
      10'd755: data = 16'h4a9;
      10'd756: data = 16'h4a8;
      10'd757: data = 16'h4a7;
      10'd758: data = 16'h4a6;
      10'd759: data = 16'h4a5;
      10'd760: data = 16'h4a5;
      10'd761: data = 16'h4a4;
      10'd762: data = 16'h4a3;
      10'd763: data = 16'h4a2;
      10'd764: data = 16'h4a2;
      10'd765: data = 16'h4a1;
      10'd766: data = 16'h4a0;
      10'd767: data = 16'h49f;
      10'd768: data = 16'h49e;
      10'd769: data = 16'h49e;
      10'd770: data = 16'h49d;
      10'd771: data = 16'h49c;
      10'd772: data = 16'h49b;
      10'd773: data = 16'h49b;
      10'd774: data = 16'h49a;
      10'd775: data = 16'h499;
      10'd776: data = 16'h498;
      10'd777: data = 16'h498;
      10'd778: data = 16'h497;
      10'd779: data = 16'h496;
      10'd780: data = 16'h495;
      10'd781: data = 16'h495;
      10'd782: data = 16'h494;
      10'd783: data = 16'h493;
      10'd784: data = 16'h492;
      10'd785: data = 16'h492;
      10'd786: data = 16'h491;
      10'd787: data = 16'h490;
      10'd788: data = 16'h48f;
      10'd789: data = 16'h48f;
      10'd790: data = 16'h48e;
      10'd791: data = 16'h48d;
      10'd792: data = 16'h48c;
      10'd793: data = 16'h48c;
      10'd794: data = 16'h48b;
      10'd795: data = 16'h48a;
      10'd796: data = 16'h489;
      10'd797: data = 16'h489;
      10'd798: data = 16'h488;
      10'd799: data = 16'h487;
      10'd800: data = 16'h487;
      10'd801: data = 16'h486;
      10'd802: data = 16'h485;
      10'd803: data = 16'h484;
      10'd804: data = 16'h484;
      10'd805: data = 16'h483;
      10'd806: data = 16'h482;
      10'd807: data = 16'h481;
      10'd808: data = 16'h481;
      10'd809: data = 16'h480;
      10'd810: data = 16'h47f;
      10'd811: data = 16'h47f;
      10'd812: data = 16'h47e;
      10'd813: data = 16'h47d;
      10'd814: data = 16'h47d;
      10'd815: data = 16'h47c;
      10'd816: data = 16'h47b;
      10'd817: data = 16'h47a;
      10'd818: data = 16'h47a;
      10'd819: data = 16'h479;
      10'd820: data = 16'h478;
      10'd821: data = 16'h478;
      10'd822: data = 16'h477;
      10'd823: data = 16'h476;
      10'd824: data = 16'h476;
      10'd825: data = 16'h475;
      10'd826: data = 16'h474;
      10'd827: data = 16'h473;
      10'd828: data = 16'h473;
      10'd829: data = 16'h472;
      10'd830: data = 16'h471;
      10'd831: data = 16'h471;
      10'd832: data = 16'h470;
      10'd833: data = 16'h46f;
      10'd834: data = 16'h46f;
      10'd835: data = 16'h46e;
      10'd836: data = 16'h46d;
      10'd837: data = 16'h46d;
      10'd838: data = 16'h46c;
      10'd839: data = 16'h46b;
      10'd840: data = 16'h46b;
      10'd841: data = 16'h46a;
      10'd842: data = 16'h469;
      10'd843: data = 16'h469;
      10'd844: data = 16'h468;
      10'd845: data = 16'h467;
      10'd846: data = 16'h467;
      10'd847: data = 16'h466;
      10'd848: data = 16'h465;
      10'd849: data = 16'h465;
      10'd850: data = 16'h464;
      10'd851: data = 16'h463;
      10'd852: data = 16'h463;
      10'd853: data = 16'h462;
      10'd854: data = 16'h461;
      10'd855: data = 16'h461;
      10'd856: data = 16'h460;
      10'd857: data = 16'h45f;
      10'd858: data = 16'h45f;
      10'd859: data = 16'h45e;
      10'd860: data = 16'h45d;
      10'd861: data = 16'h45d;
      10'd862: data = 16'h45c;
      10'd863: data = 16'h45b;
      10'd864: data = 16'h45b;
      10'd865: data = 16'h45a;
      10'd866: data = 16'h45a;
      10'd867: data = 16'h459;
      10'd868: data = 16'h458;
      10'd869: data = 16'h458;
      10'd870: data = 16'h457;
      10'd871: data = 16'h456;
      10'd872: data = 16'h456;
      10'd873: data = 16'h455;
      10'd874: data = 16'h454;
      10'd875: data = 16'h454;
      10'd876: data = 16'h453;
      10'd877: data = 16'h452;
      10'd878: data = 16'h452;
      10'd879: data = 16'h451;
      10'd880: data = 16'h451;
      10'd881: data = 16'h450;
      10'd882: data = 16'h44f;
      10'd883: data = 16'h44f;
      10'd884: data = 16'h44e;
      10'd885: data = 16'h44d;
      10'd886: data = 16'h44d;
      10'd887: data = 16'h44c;
      10'd888: data = 16'h44c;
      10'd889: data = 16'h44b;
      10'd890: data = 16'h44a;
      10'd891: data = 16'h44a;
      10'd892: data = 16'h449;
      10'd893: data = 16'h449;
      10'd894: data = 16'h448;
      10'd895: data = 16'h447;
      10'd896: data = 16'h447;
      10'd897: data = 16'h446;
      10'd898: data = 16'h445;
      10'd899: data = 16'h445;
      10'd900: data = 16'h444;
      10'd901: data = 16'h444;
      10'd902: data = 16'h443;
      10'd903: data = 16'h442;
      10'd904: data = 16'h442;
      10'd905: data = 16'h441;
      10'd906: data = 16'h441;
      10'd907: data = 16'h440;
      10'd908: data = 16'h43f;
      10'd909: data = 16'h43f;
      10'd910: data = 16'h43e;
      10'd911: data = 16'h43e;
      10'd912: data = 16'h43d;
      10'd913: data = 16'h43c;
      10'd914: data = 16'h43c;
      10'd915: data = 16'h43b;
      10'd916: data = 16'h43b;
      10'd917: data = 16'h43a;
      10'd918: data = 16'h43a;
      10'd919: data = 16'h439;
      10'd920: data = 16'h438;
      10'd921: data = 16'h438;
      10'd922: data = 16'h437;
      10'd923: data = 16'h437;
      10'd924: data = 16'h436;
      10'd925: data = 16'h435;
      10'd926: data = 16'h435;
      10'd927: data = 16'h434;
      10'd928: data = 16'h434;
      10'd929: data = 16'h433;
      10'd930: data = 16'h433;
      10'd931: data = 16'h432;
      10'd932: data = 16'h431;
      10'd933: data = 16'h431;
      10'd934: data = 16'h430;
      10'd935: data = 16'h430;
      10'd936: data = 16'h42f;
      10'd937: data = 16'h42e;
      10'd938: data = 16'h42e;
      10'd939: data = 16'h42d;
      10'd940: data = 16'h42d;
      10'd941: data = 16'h42c;
      10'd942: data = 16'h42c;
      10'd943: data = 16'h42b;
      10'd944: data = 16'h42b;
      10'd945: data = 16'h42a;
      10'd946: data = 16'h429;
      10'd947: data = 16'h429;
      10'd948: data = 16'h428;
      10'd949: data = 16'h428;
      10'd950: data = 16'h427;
      10'd951: data = 16'h427;
      10'd952: data = 16'h426;
      10'd953: data = 16'h425;
      10'd954: data = 16'h425;
      10'd955: data = 16'h424;
      10'd956: data = 16'h424;
      10'd957: data = 16'h423;
      10'd958: data = 16'h423;
      10'd959: data = 16'h422;
      10'd960: data = 16'h422;
      10'd961: data = 16'h421;
      10'd962: data = 16'h420;
      10'd963: data = 16'h420;
      10'd964: data = 16'h41f;
      10'd965: data = 16'h41f;
      10'd966: data = 16'h41e;
      10'd967: data = 16'h41e;
      10'd968: data = 16'h41d;
      10'd969: data = 16'h41d;
      10'd970: data = 16'h41c;
      10'd971: data = 16'h41c;
      10'd972: data = 16'h41b;
      10'd973: data = 16'h41a;
      10'd974: data = 16'h41a;
      10'd975: data = 16'h419;
      10'd976: data = 16'h419;
      10'd977: data = 16'h418;
      10'd978: data = 16'h418;
      10'd979: data = 16'h417;
      10'd980: data = 16'h417;
      10'd981: data = 16'h416;
      10'd982: data = 16'h416;
      10'd983: data = 16'h415;
      10'd984: data = 16'h415;
      10'd985: data = 16'h414;
      10'd986: data = 16'h414;
      10'd987: data = 16'h413;
      10'd988: data = 16'h412;
      10'd989: data = 16'h412;
      10'd990: data = 16'h411;
      10'd991: data = 16'h411;
      10'd992: data = 16'h410;
      10'd993: data = 16'h410;
      10'd994: data = 16'h40f;
      10'd995: data = 16'h40f;
      10'd996: data = 16'h40e;
      10'd997: data = 16'h40e;
      10'd998: data = 16'h40d;
      10'd999: data = 16'h40d;
      10'd1000: data = 16'h40c;
      10'd1001: data = 16'h40c;
      10'd1002: data = 16'h40b;
      10'd1003: data = 16'h40b;
      10'd1004: data = 16'h40a;
      10'd1005: data = 16'h40a;
      10'd1006: data = 16'h409;
      10'd1007: data = 16'h409;
      10'd1008: data = 16'h408;
      10'd1009: data = 16'h408;
      10'd1010: data = 16'h407;
      10'd1011: data = 16'h407;
      10'd1012: data = 16'h406;
      10'd1013: data = 16'h406;
      10'd1014: data = 16'h405;
      10'd1015: data = 16'h405;
      10'd1016: data = 16'h404;
      10'd1017: data = 16'h404;
      10'd1018: data = 16'h403;
      10'd1019: data = 16'h403;
      10'd1020: data = 16'h402;
      10'd1021: data = 16'h402;
      10'd1022: data = 16'h401;
      10'd1023: data = 16'h401;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$0$lighting$rnorm
module top$pipeline$shade$0$lighting$sh_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sh_q$0
module top$pipeline$shade$0$lighting$sh_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sh_q$1
module top$pipeline$shade$0$lighting$sh_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sh_q$2
module top$pipeline$shade$0$lighting$sl_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sl_q$0
module top$pipeline$shade$0$lighting$sl_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sl_q$1
module top$pipeline$shade$0$lighting$sl_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$sl_q$2
module top$pipeline$shade$0$lighting$specular_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$specular_q
module top$pipeline$shade$0$lighting$specular_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h31000;
    localparam  window = 24'h31400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$specular_table$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lighting$specular_table
module top$pipeline$shade$0$lighting$specular_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lighting$specular_table$ram
module top$pipeline$shade$0$lighting$square$0(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$0$lighting$square$0
module top$pipeline$shade$0$lighting$square$1(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$0$lighting$square$1
module top$pipeline$shade$0$lighting$square$2(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$0$lighting$square$2
module top$pipeline$shade$0$lighting$t_h(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$t_h
module top$pipeline$shade$0$lighting$t_l(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lighting$t_l
module top$pipeline$shade$0$lighting$third_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$third_h
module top$pipeline$shade$0$lighting$third_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$third_l
module top$pipeline$shade$0$lighting$u_h(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= 'h0;
    end
endmodule // top$pipeline$shade$0$lighting$u_h
module top$pipeline$shade$0$lighting$u_l(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= 'h0;
    end
endmodule // top$pipeline$shade$0$lighting$u_l
module top$pipeline$shade$0$lit_b(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$0$lit_b$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$lit_b$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$0$lit_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$0$lit_b$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_b
module top$pipeline$shade$0$lit_b$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_b$c_q
module top$pipeline$shade$0$lit_b$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lit_b$p
module top$pipeline$shade$0$lit_b$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_b$t
module top$pipeline$shade$0$lit_b$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_b$t_c
module top$pipeline$shade$0$lit_g(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$0$lit_g$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$lit_g$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$0$lit_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$0$lit_g$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_g
module top$pipeline$shade$0$lit_g$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_g$c_q
module top$pipeline$shade$0$lit_g$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lit_g$p
module top$pipeline$shade$0$lit_g$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_g$t
module top$pipeline$shade$0$lit_g$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_g$t_c
module top$pipeline$shade$0$lit_r(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$0$lit_r$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$lit_r$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$0$lit_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$0$lit_r$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_r
module top$pipeline$shade$0$lit_r$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_r$c_q
module top$pipeline$shade$0$lit_r$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$lit_r$p
module top$pipeline$shade$0$lit_r$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_r$t
module top$pipeline$shade$0$lit_r$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lit_r$t_c
module top$pipeline$shade$0$lut(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Constant declarations
    localparam  base = 24'h10000;
    localparam  window = 24'h11000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lut$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 64'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lut
module top$pipeline$shade$0$lut$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[255:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[7:0]][31:24], 8'd0, mem[read_address[7:0]][23:16], 8'd0, mem[read_address[7:0]][15:8], 8'd0, mem[read_address[7:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lut$ram
module top$pipeline$shade$0$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$0
module top$pipeline$shade$0$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$1
module top$pipeline$shade$0$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$2
module top$pipeline$shade$0$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$3
module top$pipeline$shade$0$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$4
module top$pipeline$shade$0$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$5
module top$pipeline$shade$0$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$6
module top$pipeline$shade$0$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$7
module top$pipeline$shade$0$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lut_q$8
module top$pipeline$shade$0$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mag_in$0
module top$pipeline$shade$0$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mag_in$1
module top$pipeline$shade$0$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mag_in$2
module top$pipeline$shade$0$mul_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_b$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$mul_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_b
module top$pipeline$shade$0$mul_b$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$mul_b$p
module top$pipeline$shade$0$mul_b$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mul_b$t
module top$pipeline$shade$0$mul_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_g$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$mul_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_g
module top$pipeline$shade$0$mul_g$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$mul_g$p
module top$pipeline$shade$0$mul_g$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mul_g$t
module top$pipeline$shade$0$mul_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_r$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$0$mul_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_r
module top$pipeline$shade$0$mul_r$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$0$mul_r$p
module top$pipeline$shade$0$mul_r$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$mul_r$t
module top$pipeline$shade$0$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$neg_in$0
module top$pipeline$shade$0$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$neg_in$1
module top$pipeline$shade$0$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$neg_in$2
module top$pipeline$shade$0$normal(clock,neg$0,neg$1,neg$2,mag$0,mag$1,mag$2,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2);
    
    // Module arguments
    input wire  clock;
    input wire  neg$0;
    input wire  neg$1;
    input wire  neg$2;
    input wire  [31:0] mag$0;
    input wire  [31:0] mag$1;
    input wire  [31:0] mag$2;
    output reg  q_neg$0;
    output reg  q_neg$1;
    output reg  q_neg$2;
    output reg  [6:0] q_mag$0;
    output reg  [6:0] q_mag$1;
    output reg  [6:0] q_mag$2;
    
    // Constant declarations
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  one = 8'h1;
    localparam  mag_bits = 8'h4;
    localparam  limit = 'hf;
    localparam  mask = 7'b1111;
    
    // Stub signals
    reg  [7:0] s_q$d;
    wire  [7:0] s_q$q;
    reg  s_q$clock;
    reg  neg_q$0$d;
    wire  neg_q$0$q;
    reg  neg_q$0$clock;
    reg  neg_q$1$d;
    wire  neg_q$1$q;
    reg  neg_q$1$clock;
    reg  neg_q$2$d;
    wire  neg_q$2$q;
    reg  neg_q$2$clock;
    reg  [31:0] mag_q$0$d;
    wire  [31:0] mag_q$0$q;
    reg  mag_q$0$clock;
    reg  [31:0] mag_q$1$d;
    wire  [31:0] mag_q$1$q;
    reg  mag_q$1$clock;
    reg  [31:0] mag_q$2$d;
    wire  [31:0] mag_q$2$q;
    reg  mag_q$2$clock;
    reg  [31:0] smear_q$d;
    wire  [31:0] smear_q$q;
    reg  smear_q$clock;
    reg  [31:0] half_q$d;
    wire  [31:0] half_q$q;
    reg  half_q$clock;
    reg  [31:0] half_m1_q$d;
    wire  [31:0] half_m1_q$q;
    reg  half_m1_q$clock;
    reg  [7:0] s_q2$d;
    wire  [7:0] s_q2$q;
    reg  s_q2$clock;
    reg  neg_q2$0$d;
    wire  neg_q2$0$q;
    reg  neg_q2$0$clock;
    reg  neg_q2$1$d;
    wire  neg_q2$1$q;
    reg  neg_q2$1$clock;
    reg  neg_q2$2$d;
    wire  neg_q2$2$q;
    reg  neg_q2$2$clock;
    reg  [31:0] sum_q$0$d;
    wire  [31:0] sum_q$0$q;
    reg  sum_q$0$clock;
    reg  [31:0] sum_q$1$d;
    wire  [31:0] sum_q$1$q;
    reg  sum_q$1$clock;
    reg  [31:0] sum_q$2$d;
    wire  [31:0] sum_q$2$q;
    reg  sum_q$2$clock;
    reg  [31:0] nz_mask_q$d;
    wire  [31:0] nz_mask_q$q;
    reg  nz_mask_q$clock;
    reg  [31:0] sat_mask_q$d;
    wire  [31:0] sat_mask_q$q;
    reg  sat_mask_q$clock;
    reg  out_neg$0$d;
    wire  out_neg$0$q;
    reg  out_neg$0$clock;
    reg  out_neg$1$d;
    wire  out_neg$1$q;
    reg  out_neg$1$clock;
    reg  out_neg$2$d;
    wire  out_neg$2$q;
    reg  out_neg$2$clock;
    reg  [6:0] out_mag$0$d;
    wire  [6:0] out_mag$0$q;
    reg  out_mag$0$clock;
    reg  [6:0] out_mag$1$d;
    wire  [6:0] out_mag$1$q;
    reg  out_mag$1$clock;
    reg  [6:0] out_mag$2$d;
    wire  [6:0] out_mag$2$q;
    reg  out_mag$2$clock;
    
    // Local signals
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [31:0] smear;
    reg  [6:0] q$0;
    reg  [6:0] q$1;
    reg  [6:0] q$2;
    
    // Sub module instances
    top$pipeline$shade$0$normal$s_q s_q(
        .d(s_q$d),
        .q(s_q$q),
        .clock(s_q$clock)
    );
    top$pipeline$shade$0$normal$neg_q$0 neg_q$0(
        .d(neg_q$0$d),
        .q(neg_q$0$q),
        .clock(neg_q$0$clock)
    );
    top$pipeline$shade$0$normal$neg_q$1 neg_q$1(
        .d(neg_q$1$d),
        .q(neg_q$1$q),
        .clock(neg_q$1$clock)
    );
    top$pipeline$shade$0$normal$neg_q$2 neg_q$2(
        .d(neg_q$2$d),
        .q(neg_q$2$q),
        .clock(neg_q$2$clock)
    );
    top$pipeline$shade$0$normal$mag_q$0 mag_q$0(
        .d(mag_q$0$d),
        .q(mag_q$0$q),
        .clock(mag_q$0$clock)
    );
    top$pipeline$shade$0$normal$mag_q$1 mag_q$1(
        .d(mag_q$1$d),
        .q(mag_q$1$q),
        .clock(mag_q$1$clock)
    );
    top$pipeline$shade$0$normal$mag_q$2 mag_q$2(
        .d(mag_q$2$d),
        .q(mag_q$2$q),
        .clock(mag_q$2$clock)
    );
    top$pipeline$shade$0$normal$smear_q smear_q(
        .d(smear_q$d),
        .q(smear_q$q),
        .clock(smear_q$clock)
    );
    top$pipeline$shade$0$normal$half_q half_q(
        .d(half_q$d),
        .q(half_q$q),
        .clock(half_q$clock)
    );
    top$pipeline$shade$0$normal$half_m1_q half_m1_q(
        .d(half_m1_q$d),
        .q(half_m1_q$q),
        .clock(half_m1_q$clock)
    );
    top$pipeline$shade$0$normal$s_q2 s_q2(
        .d(s_q2$d),
        .q(s_q2$q),
        .clock(s_q2$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$0 neg_q2$0(
        .d(neg_q2$0$d),
        .q(neg_q2$0$q),
        .clock(neg_q2$0$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$1 neg_q2$1(
        .d(neg_q2$1$d),
        .q(neg_q2$1$q),
        .clock(neg_q2$1$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$2 neg_q2$2(
        .d(neg_q2$2$d),
        .q(neg_q2$2$q),
        .clock(neg_q2$2$clock)
    );
    top$pipeline$shade$0$normal$sum_q$0 sum_q$0(
        .d(sum_q$0$d),
        .q(sum_q$0$q),
        .clock(sum_q$0$clock)
    );
    top$pipeline$shade$0$normal$sum_q$1 sum_q$1(
        .d(sum_q$1$d),
        .q(sum_q$1$q),
        .clock(sum_q$1$clock)
    );
    top$pipeline$shade$0$normal$sum_q$2 sum_q$2(
        .d(sum_q$2$d),
        .q(sum_q$2$q),
        .clock(sum_q$2$clock)
    );
    top$pipeline$shade$0$normal$nz_mask_q nz_mask_q(
        .d(nz_mask_q$d),
        .q(nz_mask_q$q),
        .clock(nz_mask_q$clock)
    );
    top$pipeline$shade$0$normal$sat_mask_q sat_mask_q(
        .d(sat_mask_q$d),
        .q(sat_mask_q$q),
        .clock(sat_mask_q$clock)
    );
    top$pipeline$shade$0$normal$out_neg$0 out_neg$0(
        .d(out_neg$0$d),
        .q(out_neg$0$q),
        .clock(out_neg$0$clock)
    );
    top$pipeline$shade$0$normal$out_neg$1 out_neg$1(
        .d(out_neg$1$d),
        .q(out_neg$1$q),
        .clock(out_neg$1$clock)
    );
    top$pipeline$shade$0$normal$out_neg$2 out_neg$2(
        .d(out_neg$2$d),
        .q(out_neg$2$q),
        .clock(out_neg$2$clock)
    );
    top$pipeline$shade$0$normal$out_mag$0 out_mag$0(
        .d(out_mag$0$d),
        .q(out_mag$0$q),
        .clock(out_mag$0$clock)
    );
    top$pipeline$shade$0$normal$out_mag$1 out_mag$1(
        .d(out_mag$1$d),
        .q(out_mag$1$q),
        .clock(out_mag$1$clock)
    );
    top$pipeline$shade$0$normal$out_mag$2 out_mag$2(
        .d(out_mag$2$d),
        .q(out_mag$2$q),
        .clock(out_mag$2$clock)
    );
    
    // Update code
    always @(*) begin
        s_q$clock = clock;
        s_q2$clock = clock;
        nz_mask_q$clock = clock;
        sat_mask_q$clock = clock;
        smear_q$clock = clock;
        half_q$clock = clock;
        half_m1_q$clock = clock;
        s_q$d = s_q$q;
        s_q2$d = s_q2$q;
        nz_mask_q$d = nz_mask_q$q;
        sat_mask_q$d = sat_mask_q$q;
        smear_q$d = smear_q$q;
        half_q$d = half_q$q;
        half_m1_q$d = half_m1_q$q;
        m = mag$0 | mag$1 | mag$2;
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s_q$d = 'h0;
        if (bl > mag_bits) begin
            s_q$d = bl - mag_bits;
        end
        smear = m | (m >> 'h1);
        smear = smear | (smear >> 'h2);
        smear = smear | (smear >> 'h4);
        smear = smear | (smear >> 'h8);
        smear = smear | (smear >> 'h10);
        smear_q$d = smear;
        half_q$d = (smear ^ (smear >> one)) >> mag_bits;
        half_m1_q$d = smear >> (mag_bits + one);
        s_q2$d = s_q$q;
        nz_mask_q$d = ~(smear_q$q >> mag_bits);
        sat_mask_q$d = ~(smear_q$q | limit);
        q$0 = 7'(sum_q$0$q >> s_q2$q);
        q$1 = 7'(sum_q$1$q >> s_q2$q);
        q$2 = 7'(sum_q$2$q >> s_q2$q);
        neg_q$0$clock = clock;
        mag_q$0$clock = clock;
        neg_q2$0$clock = clock;
        sum_q$0$clock = clock;
        out_neg$0$clock = clock;
        out_mag$0$clock = clock;
        neg_q$0$d = neg$0;
        mag_q$0$d = mag$0;
        neg_q2$0$d = neg_q$0$q;
        sum_q$0$d = mag_q$0$q + half_q$q;
        if (neg_q$0$q) begin
            sum_q$0$d = mag_q$0$q + half_m1_q$q;
        end
        out_mag$0$d = q$0 & mask;
        if ((sum_q$0$q & sat_mask_q$q) != 'h0) begin
            out_mag$0$d = mask;
        end
        out_neg$0$d = neg_q2$0$q & ((sum_q$0$q & nz_mask_q$q) != 'h0);
        q_neg$0 = out_neg$0$q;
        q_mag$0 = out_mag$0$q;
        neg_q$1$clock = clock;
        mag_q$1$clock = clock;
        neg_q2$1$clock = clock;
        sum_q$1$clock = clock;
        out_neg$1$clock = clock;
        out_mag$1$clock = clock;
        neg_q$1$d = neg$1;
        mag_q$1$d = mag$1;
        neg_q2$1$d = neg_q$1$q;
        sum_q$1$d = mag_q$1$q + half_q$q;
        if (neg_q$1$q) begin
            sum_q$1$d = mag_q$1$q + half_m1_q$q;
        end
        out_mag$1$d = q$1 & mask;
        if ((sum_q$1$q & sat_mask_q$q) != 'h0) begin
            out_mag$1$d = mask;
        end
        out_neg$1$d = neg_q2$1$q & ((sum_q$1$q & nz_mask_q$q) != 'h0);
        q_neg$1 = out_neg$1$q;
        q_mag$1 = out_mag$1$q;
        neg_q$2$clock = clock;
        mag_q$2$clock = clock;
        neg_q2$2$clock = clock;
        sum_q$2$clock = clock;
        out_neg$2$clock = clock;
        out_mag$2$clock = clock;
        neg_q$2$d = neg$2;
        mag_q$2$d = mag$2;
        neg_q2$2$d = neg_q$2$q;
        sum_q$2$d = mag_q$2$q + half_q$q;
        if (neg_q$2$q) begin
            sum_q$2$d = mag_q$2$q + half_m1_q$q;
        end
        out_mag$2$d = q$2 & mask;
        if ((sum_q$2$q & sat_mask_q$q) != 'h0) begin
            out_mag$2$d = mask;
        end
        out_neg$2$d = neg_q2$2$q & ((sum_q$2$q & nz_mask_q$q) != 'h0);
        q_neg$2 = out_neg$2$q;
        q_mag$2 = out_mag$2$q;
    end
    
endmodule // top$pipeline$shade$0$normal
module top$pipeline$shade$0$normal$half_m1_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$half_m1_q
module top$pipeline$shade$0$normal$half_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$half_q
module top$pipeline$shade$0$normal$mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$mag_q$0
module top$pipeline$shade$0$normal$mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$mag_q$1
module top$pipeline$shade$0$normal$mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$mag_q$2
module top$pipeline$shade$0$normal$neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q$0
module top$pipeline$shade$0$normal$neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q$1
module top$pipeline$shade$0$normal$neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q$2
module top$pipeline$shade$0$normal$neg_q2$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q2$0
module top$pipeline$shade$0$normal$neg_q2$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q2$1
module top$pipeline$shade$0$normal$neg_q2$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$neg_q2$2
module top$pipeline$shade$0$normal$nz_mask_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$nz_mask_q
module top$pipeline$shade$0$normal$out_mag$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$0
module top$pipeline$shade$0$normal$out_mag$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$1
module top$pipeline$shade$0$normal$out_mag$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$2
module top$pipeline$shade$0$normal$out_neg$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_neg$0
module top$pipeline$shade$0$normal$out_neg$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_neg$1
module top$pipeline$shade$0$normal$out_neg$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_neg$2
module top$pipeline$shade$0$normal$s_q(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$s_q
module top$pipeline$shade$0$normal$s_q2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$s_q2
module top$pipeline$shade$0$normal$sat_mask_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$sat_mask_q
module top$pipeline$shade$0$normal$smear_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$smear_q
module top$pipeline$shade$0$normal$sum_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$sum_q$0
module top$pipeline$shade$0$normal$sum_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$sum_q$1
module top$pipeline$shade$0$normal$sum_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$sum_q$2
module top$pipeline$shade$0$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$r_q
module top$pipeline$shade$0$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$0
module top$pipeline$shade$0$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$1
module top$pipeline$shade$0$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$2
module top$pipeline$shade$0$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$3
module top$pipeline$shade$0$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$shaded_q$0
module top$pipeline$shade$0$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$shaded_q$1
module top$pipeline$shade$0$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$shaded_q$2
module top$pipeline$shade$0$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$0
module top$pipeline$shade$0$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$1
module top$pipeline$shade$0$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$10
module top$pipeline$shade$0$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$11
module top$pipeline$shade$0$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$12
module top$pipeline$shade$0$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$13
module top$pipeline$shade$0$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$14
module top$pipeline$shade$0$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$15
module top$pipeline$shade$0$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$16
module top$pipeline$shade$0$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$2
module top$pipeline$shade$0$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$3
module top$pipeline$shade$0$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$4
module top$pipeline$shade$0$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$5
module top$pipeline$shade$0$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$6
module top$pipeline$shade$0$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$7
module top$pipeline$shade$0$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$8
module top$pipeline$shade$0$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$valid_q$9
module top$pipeline$shade$0$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$0
module top$pipeline$shade$0$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$1
module top$pipeline$shade$0$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$10
module top$pipeline$shade$0$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$11
module top$pipeline$shade$0$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$12
module top$pipeline$shade$0$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$13
module top$pipeline$shade$0$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$14
module top$pipeline$shade$0$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$15
module top$pipeline$shade$0$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$2
module top$pipeline$shade$0$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$3
module top$pipeline$shade$0$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$4
module top$pipeline$shade$0$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$5
module top$pipeline$shade$0$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$6
module top$pipeline$shade$0$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$7
module top$pipeline$shade$0$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$8
module top$pipeline$shade$0$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$value_q$9
module top$pipeline$shade$1(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b0;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b1;
    localparam  edge_transparent = 1'b1;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0;
    wire  normal$q_neg$1;
    wire  normal$q_neg$2;
    wire  [6:0] normal$q_mag$0;
    wire  [6:0] normal$q_mag$1;
    wire  [6:0] normal$q_mag$2;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [6:0] lighting$q_mag$0;
    reg  [6:0] lighting$q_mag$1;
    reg  [6:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse;
    wire  [15:0] lighting$specular;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] alpha_q$9$d;
    wire  [15:0] alpha_q$9$q;
    reg  alpha_q$9$clock;
    reg  [15:0] alpha_q$10$d;
    wire  [15:0] alpha_q$10$q;
    reg  alpha_q$10$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  [15:0] value_q$14$d;
    wire  [15:0] value_q$14$q;
    reg  value_q$14$clock;
    reg  [15:0] value_q$15$d;
    wire  [15:0] value_q$15$q;
    reg  value_q$15$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  valid_q$15$d;
    wire  valid_q$15$q;
    reg  valid_q$15$clock;
    reg  valid_q$16$d;
    wire  valid_q$16$q;
    reg  valid_q$16$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    reg  [15:0] lit_r$c;
    wire  [15:0] lit_r$y;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    reg  [15:0] lit_g$c;
    wire  [15:0] lit_g$y;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    reg  [15:0] lit_b$c;
    wire  [15:0] lit_b$y;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    
    // Sub module instances
    top$pipeline$shade$1$lut lut(
        .clock(lut$clock),
        .host_write(lut$host_write),
        .host_address(lut$host_address),
        .host_data(lut$host_data),
        .address(lut$address),
        .data(lut$data)
    );
    top$pipeline$shade$1$normal normal(
        .clock(normal$clock),
        .neg$0(normal$neg$0),
        .neg$1(normal$neg$1),
        .neg$2(normal$neg$2),
        .mag$0(normal$mag$0),
        .mag$1(normal$mag$1),
        .mag$2(normal$mag$2),
        .q_neg$0(normal$q_neg$0),
        .q_neg$1(normal$q_neg$1),
        .q_neg$2(normal$q_neg$2),
        .q_mag$0(normal$q_mag$0),
        .q_mag$1(normal$q_mag$1),
        .q_mag$2(normal$q_mag$2)
    );
    top$pipeline$shade$1$lighting lighting(
        .clock(lighting$clock),
        .host_write(lighting$host_write),
        .host_address(lighting$host_address),
        .host_data(lighting$host_data),
        .q_neg$0(lighting$q_neg$0),
        .q_neg$1(lighting$q_neg$1),
        .q_neg$2(lighting$q_neg$2),
        .q_mag$0(lighting$q_mag$0),
        .q_mag$1(lighting$q_mag$1),
        .q_mag$2(lighting$q_mag$2),
        .diffuse(lighting$diffuse),
        .specular(lighting$specular)
    );
    top$pipeline$shade$1$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$pipeline$shade$1$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$pipeline$shade$1$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$pipeline$shade$1$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$pipeline$shade$1$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$pipeline$shade$1$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$pipeline$shade$1$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$pipeline$shade$1$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$pipeline$shade$1$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$pipeline$shade$1$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$pipeline$shade$1$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$pipeline$shade$1$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$pipeline$shade$1$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$pipeline$shade$1$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$pipeline$shade$1$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$pipeline$shade$1$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$pipeline$shade$1$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$pipeline$shade$1$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$pipeline$shade$1$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$pipeline$shade$1$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$pipeline$shade$1$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$pipeline$shade$1$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$pipeline$shade$1$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$pipeline$shade$1$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$pipeline$shade$1$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$pipeline$shade$1$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$pipeline$shade$1$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$pipeline$shade$1$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$pipeline$shade$1$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$pipeline$shade$1$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$pipeline$shade$1$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$pipeline$shade$1$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$pipeline$shade$1$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$pipeline$shade$1$alpha_q$9 alpha_q$9(
        .d(alpha_q$9$d),
        .q(alpha_q$9$q),
        .clock(alpha_q$9$clock)
    );
    top$pipeline$shade$1$alpha_q$10 alpha_q$10(
        .d(alpha_q$10$d),
        .q(alpha_q$10$q),
        .clock(alpha_q$10$clock)
    );
    top$pipeline$shade$1$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$pipeline$shade$1$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$pipeline$shade$1$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$pipeline$shade$1$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$pipeline$shade$1$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$pipeline$shade$1$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$pipeline$shade$1$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$pipeline$shade$1$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$pipeline$shade$1$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$pipeline$shade$1$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$pipeline$shade$1$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$pipeline$shade$1$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$pipeline$shade$1$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$pipeline$shade$1$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$pipeline$shade$1$value_q$14 value_q$14(
        .d(value_q$14$d),
        .q(value_q$14$q),
        .clock(value_q$14$clock)
    );
    top$pipeline$shade$1$value_q$15 value_q$15(
        .d(value_q$15$d),
        .q(value_q$15$q),
        .clock(value_q$15$clock)
    );
    top$pipeline$shade$1$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$pipeline$shade$1$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$pipeline$shade$1$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$pipeline$shade$1$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$pipeline$shade$1$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$pipeline$shade$1$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$pipeline$shade$1$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$pipeline$shade$1$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$pipeline$shade$1$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$pipeline$shade$1$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$pipeline$shade$1$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$pipeline$shade$1$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$pipeline$shade$1$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$pipeline$shade$1$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$pipeline$shade$1$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$pipeline$shade$1$valid_q$15 valid_q$15(
        .d(valid_q$15$d),
        .q(valid_q$15$q),
        .clock(valid_q$15$clock)
    );
    top$pipeline$shade$1$valid_q$16 valid_q$16(
        .d(valid_q$16$d),
        .q(valid_q$16$q),
        .clock(valid_q$16$clock)
    );
    top$pipeline$shade$1$lit_r lit_r(
        .clock(lit_r$clock),
        .a(lit_r$a),
        .b(lit_r$b),
        .c(lit_r$c),
        .y(lit_r$y)
    );
    top$pipeline$shade$1$lit_g lit_g(
        .clock(lit_g$clock),
        .a(lit_g$a),
        .b(lit_g$b),
        .c(lit_g$c),
        .y(lit_g$y)
    );
    top$pipeline$shade$1$lit_b lit_b(
        .clock(lit_b$clock),
        .a(lit_b$a),
        .b(lit_b$b),
        .c(lit_b$c),
        .y(lit_b$y)
    );
    top$pipeline$shade$1$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$pipeline$shade$1$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$pipeline$shade$1$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$pipeline$shade$1$mul_r mul_r(
        .clock(mul_r$clock),
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$pipeline$shade$1$mul_g mul_g(
        .clock(mul_g$clock),
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$pipeline$shade$1$mul_b mul_b(
        .clock(mul_b$clock),
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$pipeline$shade$1$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$pipeline$shade$1$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$pipeline$shade$1$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$pipeline$shade$1$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        lut_q$1$clock = clock;
        lut_q$2$clock = clock;
        lut_q$3$clock = clock;
        lut_q$4$clock = clock;
        lut_q$5$clock = clock;
        lut_q$6$clock = clock;
        lut_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$0$clock = clock;
        alpha_q$1$clock = clock;
        alpha_q$2$clock = clock;
        alpha_q$3$clock = clock;
        alpha_q$4$clock = clock;
        alpha_q$5$clock = clock;
        alpha_q$6$clock = clock;
        alpha_q$7$clock = clock;
        alpha_q$8$clock = clock;
        alpha_q$9$clock = clock;
        alpha_q$10$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        value_q$14$clock = clock;
        value_q$15$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        valid_q$15$clock = clock;
        valid_q$16$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        value_q$14$d = value_q$13$q;
        value_q$15$d = value_q$14$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        valid_q$15$d = valid_q$14$q;
        valid_q$16$d = valid_q$15$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        alpha_q$9$d = alpha_q$8$q;
        alpha_q$10$d = alpha_q$9$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        lit_r$c = specular;
        lit_g$c = specular;
        lit_b$c = specular;
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = lit_r$y;
        shaded_q$1$d = lit_g$y;
        shaded_q$2$d = lit_b$y;
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$8$q;
        mul_g$b = alpha_q$8$q;
        mul_b$b = alpha_q$8$q;
        if (scalar) begin
            r_q$d = value_q$15$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$10$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$10$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$16$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$pipeline$shade$1
module top$pipeline$shade$1$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$a_q
module top$pipeline$shade$1$alpha_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$0
module top$pipeline$shade$1$alpha_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$1
module top$pipeline$shade$1$alpha_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$10
module top$pipeline$shade$1$alpha_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$2
module top$pipeline$shade$1$alpha_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$3
module top$pipeline$shade$1$alpha_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$4
module top$pipeline$shade$1$alpha_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$5
module top$pipeline$shade$1$alpha_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$6
module top$pipeline$shade$1$alpha_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$7
module top$pipeline$shade$1$alpha_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$8
module top$pipeline$shade$1$alpha_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$alpha_q$9
module top$pipeline$shade$1$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$b_q
module top$pipeline$shade$1$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$g_q
module top$pipeline$shade$1$gate_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$gate_q$0
module top$pipeline$shade$1$gate_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$gate_q$1
module top$pipeline$shade$1$gate_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$gate_q$2
module top$pipeline$shade$1$gate_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$gate_q$3
module top$pipeline$shade$1$gate_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$gate_q$4
module top$pipeline$shade$1$lighting(clock,host_write,host_address,host_data,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2,diffuse,specular);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  q_neg$0;
    input wire  q_neg$1;
    input wire  q_neg$2;
    input wire  [6:0] q_mag$0;
    input wire  [6:0] q_mag$1;
    input wire  [6:0] q_mag$2;
    output reg  [15:0] diffuse;
    output reg  [15:0] specular;
    
    // Constant declarations
    localparam  saturation = 'hffff;
    localparam  wide_dot = 1'b0;
    localparam  half_ulp = 64'h2000000;
    localparam  shift = 8'h1a;
    localparam  last = 10'b1111111111;
    localparam  sat_t = 64'h4008021;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    reg  [15:0] rnorm$address;
    wire  [15:0] rnorm$data;
    reg  [6:0] square$0$address;
    wire  [15:0] square$0$data;
    reg  [6:0] square$1$address;
    wire  [15:0] square$1$data;
    reg  [6:0] square$2$address;
    wire  [15:0] square$2$data;
    reg  diffuse_table$clock;
    reg  diffuse_table$host_write;
    reg  [23:0] diffuse_table$host_address;
    reg  [63:0] diffuse_table$host_data;
    reg  [9:0] diffuse_table$address;
    wire  [15:0] diffuse_table$data;
    reg  specular_table$clock;
    reg  specular_table$host_write;
    reg  [23:0] specular_table$host_address;
    reg  [63:0] specular_table$host_data;
    reg  [9:0] specular_table$address;
    wire  [15:0] specular_table$data;
    reg  [15:0] ml_q$0$d;
    wire  [15:0] ml_q$0$q;
    reg  ml_q$0$clock;
    reg  [15:0] ml_q$1$d;
    wire  [15:0] ml_q$1$q;
    reg  ml_q$1$clock;
    reg  [15:0] ml_q$2$d;
    wire  [15:0] ml_q$2$q;
    reg  ml_q$2$clock;
    reg  [15:0] mh_q$0$d;
    wire  [15:0] mh_q$0$q;
    reg  mh_q$0$clock;
    reg  [15:0] mh_q$1$d;
    wire  [15:0] mh_q$1$q;
    reg  mh_q$1$clock;
    reg  [15:0] mh_q$2$d;
    wire  [15:0] mh_q$2$q;
    reg  mh_q$2$clock;
    reg  p_l$0$clock;
    reg  [15:0] p_l$0$a;
    reg  [15:0] p_l$0$b;
    wire  [31:0] p_l$0$p;
    reg  p_l$1$clock;
    reg  [15:0] p_l$1$a;
    reg  [15:0] p_l$1$b;
    wire  [31:0] p_l$1$p;
    reg  p_l$2$clock;
    reg  [15:0] p_l$2$a;
    reg  [15:0] p_l$2$b;
    wire  [31:0] p_l$2$p;
    reg  p_h$0$clock;
    reg  [15:0] p_h$0$a;
    reg  [15:0] p_h$0$b;
    wire  [31:0] p_h$0$p;
    reg  p_h$1$clock;
    reg  [15:0] p_h$1$a;
    reg  [15:0] p_h$1$b;
    wire  [31:0] p_h$1$p;
    reg  p_h$2$clock;
    reg  [15:0] p_h$2$a;
    reg  [15:0] p_h$2$b;
    wire  [31:0] p_h$2$p;
    reg  sl_q$0$d;
    wire  sl_q$0$q;
    reg  sl_q$0$clock;
    reg  sl_q$1$d;
    wire  sl_q$1$q;
    reg  sl_q$1$clock;
    reg  sl_q$2$d;
    wire  sl_q$2$q;
    reg  sl_q$2$clock;
    reg  sh_q$0$d;
    wire  sh_q$0$q;
    reg  sh_q$0$clock;
    reg  sh_q$1$d;
    wire  sh_q$1$q;
    reg  sh_q$1$clock;
    reg  sh_q$2$d;
    wire  sh_q$2$q;
    reg  sh_q$2$clock;
    reg  [15:0] n2_q$d;
    wire  [15:0] n2_q$q;
    reg  n2_q$clock;
    reg  [31:0] pair_l$d;
    wire  [31:0] pair_l$q;
    reg  pair_l$clock;
    reg  [31:0] pair_h$d;
    wire  [31:0] pair_h$q;
    reg  pair_h$clock;
    reg  [31:0] third_l$d;
    wire  [31:0] third_l$q;
    reg  third_l$clock;
    reg  [31:0] third_h$d;
    wire  [31:0] third_h$q;
    reg  third_h$clock;
    reg  [15:0] rn$d;
    wire  [15:0] rn$q;
    reg  rn$clock;
    reg  [31:0] d_l$d;
    wire  [31:0] d_l$q;
    reg  d_l$clock;
    reg  [31:0] d_h$d;
    wire  [31:0] d_h$q;
    reg  d_h$clock;
    reg  [15:0] rn_3$d;
    wire  [15:0] rn_3$q;
    reg  rn_3$clock;
    reg  lit_3$d;
    wire  lit_3$q;
    reg  lit_3$clock;
    reg  t_l$clock;
    reg  [15:0] t_l$a;
    reg  [15:0] t_l$b;
    wire  [31:0] t_l$p;
    reg  t_h$clock;
    reg  [15:0] t_h$a;
    reg  [15:0] t_h$b;
    wire  [31:0] t_h$p;
    reg  u_l$clock;
    reg  [15:0] u_l$a;
    reg  [15:0] u_l$b;
    wire  [31:0] u_l$p;
    reg  u_h$clock;
    reg  [15:0] u_h$a;
    reg  [15:0] u_h$b;
    wire  [31:0] u_h$p;
    reg  lit_4$d;
    wire  lit_4$q;
    reg  lit_4$clock;
    reg  [9:0] idx_l$d;
    wire  [9:0] idx_l$q;
    reg  idx_l$clock;
    reg  [9:0] idx_h$d;
    wire  [9:0] idx_h$q;
    reg  idx_h$clock;
    reg  lit_5$d;
    wire  lit_5$q;
    reg  lit_5$clock;
    reg  lit_6$d;
    wire  lit_6$q;
    reg  lit_6$clock;
    reg  [15:0] diffuse_q$d;
    wire  [15:0] diffuse_q$q;
    reg  diffuse_q$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    
    // Local signals
    reg  [15:0] m_l$0;
    reg  [15:0] m_l$1;
    reg  [15:0] m_l$2;
    reg  [15:0] m_h$0;
    reg  [15:0] m_h$1;
    reg  [15:0] m_h$2;
    reg  [15:0] qm$0;
    reg  [15:0] qm$1;
    reg  [15:0] qm$2;
    reg  [31:0] t_pl$0;
    reg  [31:0] t_pl$1;
    reg  [31:0] t_pl$2;
    reg  [31:0] t_ph$0;
    reg  [31:0] t_ph$1;
    reg  [31:0] t_ph$2;
    reg  [31:0] c_l;
    reg  [31:0] c_h;
    reg  [15:0] n2;
    reg  [31:0] dot_l;
    reg  [31:0] dot_h;
    reg  [63:0] tt_l;
    reg  [63:0] tt_h;
    reg  [9:0] i_l;
    reg  [9:0] i_h;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1)
    );
    top$pipeline$shade$1$lighting$rnorm rnorm(
        .address(rnorm$address),
        .data(rnorm$data)
    );
    top$pipeline$shade$1$lighting$square$0 square$0(
        .address(square$0$address),
        .data(square$0$data)
    );
    top$pipeline$shade$1$lighting$square$1 square$1(
        .address(square$1$address),
        .data(square$1$data)
    );
    top$pipeline$shade$1$lighting$square$2 square$2(
        .address(square$2$address),
        .data(square$2$data)
    );
    top$pipeline$shade$1$lighting$diffuse_table diffuse_table(
        .clock(diffuse_table$clock),
        .host_write(diffuse_table$host_write),
        .host_address(diffuse_table$host_address),
        .host_data(diffuse_table$host_data),
        .address(diffuse_table$address),
        .data(diffuse_table$data)
    );
    top$pipeline$shade$1$lighting$specular_table specular_table(
        .clock(specular_table$clock),
        .host_write(specular_table$host_write),
        .host_address(specular_table$host_address),
        .host_data(specular_table$host_data),
        .address(specular_table$address),
        .data(specular_table$data)
    );
    top$pipeline$shade$1$lighting$ml_q$0 ml_q$0(
        .d(ml_q$0$d),
        .q(ml_q$0$q),
        .clock(ml_q$0$clock)
    );
    top$pipeline$shade$1$lighting$ml_q$1 ml_q$1(
        .d(ml_q$1$d),
        .q(ml_q$1$q),
        .clock(ml_q$1$clock)
    );
    top$pipeline$shade$1$lighting$ml_q$2 ml_q$2(
        .d(ml_q$2$d),
        .q(ml_q$2$q),
        .clock(ml_q$2$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$0 mh_q$0(
        .d(mh_q$0$d),
        .q(mh_q$0$q),
        .clock(mh_q$0$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$1 mh_q$1(
        .d(mh_q$1$d),
        .q(mh_q$1$q),
        .clock(mh_q$1$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$2 mh_q$2(
        .d(mh_q$2$d),
        .q(mh_q$2$q),
        .clock(mh_q$2$clock)
    );
    top$pipeline$shade$1$lighting$p_l$0 p_l$0(
        .clock(p_l$0$clock),
        .a(p_l$0$a),
        .b(p_l$0$b),
        .p(p_l$0$p)
    );
    top$pipeline$shade$1$lighting$p_l$1 p_l$1(
        .clock(p_l$1$clock),
        .a(p_l$1$a),
        .b(p_l$1$b),
        .p(p_l$1$p)
    );
    top$pipeline$shade$1$lighting$p_l$2 p_l$2(
        .clock(p_l$2$clock),
        .a(p_l$2$a),
        .b(p_l$2$b),
        .p(p_l$2$p)
    );
    top$pipeline$shade$1$lighting$p_h$0 p_h$0(
        .clock(p_h$0$clock),
        .a(p_h$0$a),
        .b(p_h$0$b),
        .p(p_h$0$p)
    );
    top$pipeline$shade$1$lighting$p_h$1 p_h$1(
        .clock(p_h$1$clock),
        .a(p_h$1$a),
        .b(p_h$1$b),
        .p(p_h$1$p)
    );
    top$pipeline$shade$1$lighting$p_h$2 p_h$2(
        .clock(p_h$2$clock),
        .a(p_h$2$a),
        .b(p_h$2$b),
        .p(p_h$2$p)
    );
    top$pipeline$shade$1$lighting$sl_q$0 sl_q$0(
        .d(sl_q$0$d),
        .q(sl_q$0$q),
        .clock(sl_q$0$clock)
    );
    top$pipeline$shade$1$lighting$sl_q$1 sl_q$1(
        .d(sl_q$1$d),
        .q(sl_q$1$q),
        .clock(sl_q$1$clock)
    );
    top$pipeline$shade$1$lighting$sl_q$2 sl_q$2(
        .d(sl_q$2$d),
        .q(sl_q$2$q),
        .clock(sl_q$2$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$0 sh_q$0(
        .d(sh_q$0$d),
        .q(sh_q$0$q),
        .clock(sh_q$0$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$1 sh_q$1(
        .d(sh_q$1$d),
        .q(sh_q$1$q),
        .clock(sh_q$1$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$2 sh_q$2(
        .d(sh_q$2$d),
        .q(sh_q$2$q),
        .clock(sh_q$2$clock)
    );
    top$pipeline$shade$1$lighting$n2_q n2_q(
        .d(n2_q$d),
        .q(n2_q$q),
        .clock(n2_q$clock)
    );
    top$pipeline$shade$1$lighting$pair_l pair_l(
        .d(pair_l$d),
        .q(pair_l$q),
        .clock(pair_l$clock)
    );
    top$pipeline$shade$1$lighting$pair_h pair_h(
        .d(pair_h$d),
        .q(pair_h$q),
        .clock(pair_h$clock)
    );
    top$pipeline$shade$1$lighting$third_l third_l(
        .d(third_l$d),
        .q(third_l$q),
        .clock(third_l$clock)
    );
    top$pipeline$shade$1$lighting$third_h third_h(
        .d(third_h$d),
        .q(third_h$q),
        .clock(third_h$clock)
    );
    top$pipeline$shade$1$lighting$rn rn(
        .d(rn$d),
        .q(rn$q),
        .clock(rn$clock)
    );
    top$pipeline$shade$1$lighting$d_l d_l(
        .d(d_l$d),
        .q(d_l$q),
        .clock(d_l$clock)
    );
    top$pipeline$shade$1$lighting$d_h d_h(
        .d(d_h$d),
        .q(d_h$q),
        .clock(d_h$clock)
    );
    top$pipeline$shade$1$lighting$rn_3 rn_3(
        .d(rn_3$d),
        .q(rn_3$q),
        .clock(rn_3$clock)
    );
    top$pipeline$shade$1$lighting$lit_3 lit_3(
        .d(lit_3$d),
        .q(lit_3$q),
        .clock(lit_3$clock)
    );
    top$pipeline$shade$1$lighting$t_l t_l(
        .clock(t_l$clock),
        .a(t_l$a),
        .b(t_l$b),
        .p(t_l$p)
    );
    top$pipeline$shade$1$lighting$t_h t_h(
        .clock(t_h$clock),
        .a(t_h$a),
        .b(t_h$b),
        .p(t_h$p)
    );
    top$pipeline$shade$1$lighting$u_l u_l(
        .clock(u_l$clock),
        .a(u_l$a),
        .b(u_l$b),
        .p(u_l$p)
    );
    top$pipeline$shade$1$lighting$u_h u_h(
        .clock(u_h$clock),
        .a(u_h$a),
        .b(u_h$b),
        .p(u_h$p)
    );
    top$pipeline$shade$1$lighting$lit_4 lit_4(
        .d(lit_4$d),
        .q(lit_4$q),
        .clock(lit_4$clock)
    );
    top$pipeline$shade$1$lighting$idx_l idx_l(
        .d(idx_l$d),
        .q(idx_l$q),
        .clock(idx_l$clock)
    );
    top$pipeline$shade$1$lighting$idx_h idx_h(
        .d(idx_h$d),
        .q(idx_h$q),
        .clock(idx_h$clock)
    );
    top$pipeline$shade$1$lighting$lit_5 lit_5(
        .d(lit_5$d),
        .q(lit_5$q),
        .clock(lit_5$clock)
    );
    top$pipeline$shade$1$lighting$lit_6 lit_6(
        .d(lit_6$d),
        .q(lit_6$q),
        .clock(lit_6$clock)
    );
    top$pipeline$shade$1$lighting$diffuse_q diffuse_q(
        .d(diffuse_q$d),
        .q(diffuse_q$q),
        .clock(diffuse_q$clock)
    );
    top$pipeline$shade$1$lighting$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    
    // Update code
    always @(*) begin
        n2_q$clock = clock;
        pair_l$clock = clock;
        pair_h$clock = clock;
        third_l$clock = clock;
        third_h$clock = clock;
        rn$clock = clock;
        d_l$clock = clock;
        d_h$clock = clock;
        rn_3$clock = clock;
        lit_3$clock = clock;
        lit_4$clock = clock;
        idx_l$clock = clock;
        idx_h$clock = clock;
        lit_5$clock = clock;
        lit_6$clock = clock;
        diffuse_q$clock = clock;
        specular_q$clock = clock;
        n2_q$d = n2_q$q;
        pair_l$d = pair_l$q;
        pair_h$d = pair_h$q;
        third_l$d = third_l$q;
        third_h$d = third_h$q;
        rn$d = rn$q;
        d_l$d = d_l$q;
        d_h$d = d_h$q;
        rn_3$d = rn_3$q;
        lit_3$d = lit_3$q;
        lit_4$d = lit_4$q;
        idx_l$d = idx_l$q;
        idx_h$d = idx_h$q;
        lit_5$d = lit_5$q;
        lit_6$d = lit_6$q;
        diffuse_q$d = diffuse_q$q;
        specular_q$d = specular_q$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        diffuse_table$clock = clock;
        diffuse_table$host_write = host_write;
        diffuse_table$host_address = host_address;
        diffuse_table$host_data = host_data;
        specular_table$clock = clock;
        specular_table$host_write = host_write;
        specular_table$host_address = host_address;
        specular_table$host_data = host_data;
        qm$0 = 16'(q_mag$0);
        qm$1 = 16'(q_mag$1);
        qm$2 = 16'(q_mag$2);
        m_l$0 = regs$q$0[('h0)+:(16)];
        if (regs$q$0['hf]) begin
            m_l$0 = 'h0 - regs$q$0[('h0)+:(16)];
        end
        m_l$1 = regs$q$0[('h10)+:(16)];
        if (regs$q$0['h1f]) begin
            m_l$1 = 'h0 - regs$q$0[('h10)+:(16)];
        end
        m_l$2 = regs$q$0[('h20)+:(16)];
        if (regs$q$0['h2f]) begin
            m_l$2 = 'h0 - regs$q$0[('h20)+:(16)];
        end
        m_h$0 = regs$q$1[('h0)+:(16)];
        if (regs$q$1['hf]) begin
            m_h$0 = 'h0 - regs$q$1[('h0)+:(16)];
        end
        m_h$1 = regs$q$1[('h10)+:(16)];
        if (regs$q$1['h1f]) begin
            m_h$1 = 'h0 - regs$q$1[('h10)+:(16)];
        end
        m_h$2 = regs$q$1[('h20)+:(16)];
        if (regs$q$1['h2f]) begin
            m_h$2 = 'h0 - regs$q$1[('h20)+:(16)];
        end
        ml_q$0$clock = clock;
        mh_q$0$clock = clock;
        sl_q$0$clock = clock;
        sh_q$0$clock = clock;
        p_l$0$clock = clock;
        p_h$0$clock = clock;
        p_l$0$a = qm$0;
        p_h$0$a = qm$0;
        square$0$address = q_mag$0;
        ml_q$0$d = m_l$0;
        mh_q$0$d = m_h$0;
        p_l$0$b = ml_q$0$q;
        p_h$0$b = mh_q$0$q;
        ml_q$1$clock = clock;
        mh_q$1$clock = clock;
        sl_q$1$clock = clock;
        sh_q$1$clock = clock;
        p_l$1$clock = clock;
        p_h$1$clock = clock;
        p_l$1$a = qm$1;
        p_h$1$a = qm$1;
        square$1$address = q_mag$1;
        ml_q$1$d = m_l$1;
        mh_q$1$d = m_h$1;
        p_l$1$b = ml_q$1$q;
        p_h$1$b = mh_q$1$q;
        ml_q$2$clock = clock;
        mh_q$2$clock = clock;
        sl_q$2$clock = clock;
        sh_q$2$clock = clock;
        p_l$2$clock = clock;
        p_h$2$clock = clock;
        p_l$2$a = qm$2;
        p_h$2$a = qm$2;
        square$2$address = q_mag$2;
        ml_q$2$d = m_l$2;
        mh_q$2$d = m_h$2;
        p_l$2$b = ml_q$2$q;
        p_h$2$b = mh_q$2$q;
        sl_q$0$d = q_neg$0 ^ regs$q$0['hf];
        sl_q$1$d = q_neg$1 ^ regs$q$0['h1f];
        sl_q$2$d = q_neg$2 ^ regs$q$0['h2f];
        sh_q$0$d = q_neg$0 ^ regs$q$1['hf];
        sh_q$1$d = q_neg$1 ^ regs$q$1['h1f];
        sh_q$2$d = q_neg$2 ^ regs$q$1['h2f];
        n2 = square$0$data + square$1$data + square$2$data;
        n2_q$d = n2;
        t_pl$0 = p_l$0$p;
        if (sl_q$0$q) begin
            t_pl$0 = ~p_l$0$p;
        end
        t_ph$0 = p_h$0$p;
        if (sh_q$0$q) begin
            t_ph$0 = ~p_h$0$p;
        end
        t_pl$1 = p_l$1$p;
        if (sl_q$1$q) begin
            t_pl$1 = ~p_l$1$p;
        end
        t_ph$1 = p_h$1$p;
        if (sh_q$1$q) begin
            t_ph$1 = ~p_h$1$p;
        end
        t_pl$2 = p_l$2$p;
        if (sl_q$2$q) begin
            t_pl$2 = ~p_l$2$p;
        end
        t_ph$2 = p_h$2$p;
        if (sh_q$2$q) begin
            t_ph$2 = ~p_h$2$p;
        end
        c_l = 32'(sl_q$0$q) + 32'(sl_q$1$q) + 32'(sl_q$2$q);
        c_h = 32'(sh_q$0$q) + 32'(sh_q$1$q) + 32'(sh_q$2$q);
        pair_l$d = t_pl$0 + t_pl$1;
        pair_h$d = t_ph$0 + t_ph$1;
        third_l$d = t_pl$2 + c_l;
        third_h$d = t_ph$2 + c_h;
        rnorm$address = n2_q$q;
        rn$d = rnorm$data;
        dot_l = pair_l$q + third_l$q;
        dot_h = pair_h$q + third_h$q;
        d_l$d = dot_l & saturation;
        if (dot_l['h1f] | (dot_l == 'h0)) begin
            d_l$d = 'h0;
        end
        else if ((dot_l & ~saturation) != 'h0) begin
            d_l$d = saturation;
        end
        d_h$d = dot_h & saturation;
        if (dot_h['h1f] | (dot_h == 'h0)) begin
            d_h$d = 'h0;
        end
        else if ((dot_h & ~saturation) != 'h0) begin
            d_h$d = saturation;
        end
        rn_3$d = rn$q;
        lit_3$d = ~dot_l['h1f] & (dot_l != 'h0);
        t_l$clock = clock;
        t_h$clock = clock;
        u_l$clock = clock;
        u_h$clock = clock;
        t_l$a = d_l$q[('h0)+:(16)];
        t_h$a = d_h$q[('h0)+:(16)];
        u_l$a = d_l$q[('h10)+:(16)];
        u_h$a = d_h$q[('h10)+:(16)];
        t_l$b = rn_3$q;
        t_h$b = rn_3$q;
        u_l$b = rn_3$q;
        u_h$b = rn_3$q;
        lit_4$d = lit_3$q;
        tt_l = 64'(t_l$p);
        tt_h = 64'(t_h$p);
        if (wide_dot) begin
            tt_l = 64'(t_l$p) + (64'(u_l$p) << 'h10);
            tt_h = 64'(t_h$p) + (64'(u_h$p) << 'h10);
        end
        i_l = 10'(((tt_l << 'ha) - tt_l + half_ulp) >> shift);
        i_h = 10'(((tt_h << 'ha) - tt_h + half_ulp) >> shift);
        idx_l$d = i_l;
        if (tt_l >= sat_t) begin
            idx_l$d = last;
        end
        idx_h$d = i_h;
        if (tt_h >= sat_t) begin
            idx_h$d = last;
        end
        lit_5$d = lit_4$q;
        diffuse_table$address = idx_l$q;
        specular_table$address = idx_h$q;
        lit_6$d = lit_5$q;
        diffuse_q$d = diffuse_table$data;
        specular_q$d = 'h0;
        if (lit_6$q) begin
            specular_q$d = specular_table$data;
        end
        diffuse = diffuse_q$q;
        specular = specular_q$q;
    end
    
endmodule // top$pipeline$shade$1$lighting
module top$pipeline$shade$1$lighting$d_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$d_h
module top$pipeline$shade$1$lighting$d_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$d_l
module top$pipeline$shade$1$lighting$diffuse_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$diffuse_q
module top$pipeline$shade$1$lighting$diffuse_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h30000;
    localparam  window = 24'h30400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$diffuse_table$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lighting$diffuse_table
module top$pipeline$shade$1$lighting$diffuse_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lighting$diffuse_table$ram
module top$pipeline$shade$1$lighting$idx_h(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$idx_h
module top$pipeline$shade$1$lighting$idx_l(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$idx_l
module top$pipeline$shade$1$lighting$lit_3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$lit_3
module top$pipeline$shade$1$lighting$lit_4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$lit_4
module top$pipeline$shade$1$lighting$lit_5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$lit_5
module top$pipeline$shade$1$lighting$lit_6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$lit_6
module top$pipeline$shade$1$lighting$mh_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$mh_q$0
module top$pipeline$shade$1$lighting$mh_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$mh_q$1
module top$pipeline$shade$1$lighting$mh_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$mh_q$2
module top$pipeline$shade$1$lighting$ml_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$ml_q$0
module top$pipeline$shade$1$lighting$ml_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$ml_q$1
module top$pipeline$shade$1$lighting$ml_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$ml_q$2
module top$pipeline$shade$1$lighting$n2_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$n2_q
module top$pipeline$shade$1$lighting$p_h$0(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_h$0
module top$pipeline$shade$1$lighting$p_h$1(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_h$1
module top$pipeline$shade$1$lighting$p_h$2(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_h$2
module top$pipeline$shade$1$lighting$p_l$0(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_l$0
module top$pipeline$shade$1$lighting$p_l$1(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_l$1
module top$pipeline$shade$1$lighting$p_l$2(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$p_l$2
module top$pipeline$shade$1$lighting$pair_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$pair_h
module top$pipeline$shade$1$lighting$pair_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$pair_l
module top$pipeline$shade$1$lighting$regs(clock,host_write,host_address,host_data,q$0,q$1);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    
    // Constant declarations
    localparam  address$0 = 24'h10;
    localparam  address$1 = 24'h11;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$shade$1$lighting$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
    end
    
endmodule // top$pipeline$shade$1$lighting$regs
module top$pipeline$shade$1$lighting$regs$r$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$regs$r$0
module top$pipeline$shade$1$lighting$regs$r$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$regs$r$1
module top$pipeline$shade$1$lighting$rn(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$rn
module top$pipeline$shade$1$lighting$rn_3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$rn_3
module top$pipeline$shade$1$lighting$rnorm(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[9:0])
      10'd0: data = 16'h0;
      10'd1: data = 16'h8000;
      10'd2: data = 16'h5a82;
      10'd3: data = 16'h49e7;
      10'd4: data = 16'h4000;
      10'd5: data = 16'h393e;
      10'd6: data = 16'h3441;
      10'd7: data = 16'h3061;
      10'd8: data = 16'h2d41;
      10'd9: data = 16'h2aab;
      10'd10: data = 16'h287a;
      10'd11: data = 16'h2698;
      10'd12: data = 16'h24f3;
      10'd13: data = 16'h2380;
      10'd14: data = 16'h2236;
      10'd15: data = 16'h210d;
      10'd16: data = 16'h2000;
      10'd17: data = 16'h1f0b;
      10'd18: data = 16'h1e2b;
      10'd19: data = 16'h1d5d;
      10'd20: data = 16'h1c9f;
      10'd21: data = 16'h1bef;
      10'd22: data = 16'h1b4a;
      10'd23: data = 16'h1ab1;
      10'd24: data = 16'h1a21;
      10'd25: data = 16'h199a;
      10'd26: data = 16'h191a;
      10'd27: data = 16'h18a2;
      10'd28: data = 16'h1831;
      10'd29: data = 16'h17c5;
      10'd30: data = 16'h175f;
      10'd31: data = 16'h16fd;
      10'd32: data = 16'h16a1;
      10'd33: data = 16'h1648;
      10'd34: data = 16'h15f4;
      10'd35: data = 16'h15a3;
      10'd36: data = 16'h1555;
      10'd37: data = 16'h150b;
      10'd38: data = 16'h14c4;
      10'd39: data = 16'h147f;
      10'd40: data = 16'h143d;
      10'd41: data = 16'h13fe;
      10'd42: data = 16'h13c0;
      10'd43: data = 16'h1385;
      10'd44: data = 16'h134c;
      10'd45: data = 16'h1315;
      10'd46: data = 16'h12df;
      10'd47: data = 16'h12ac;
      10'd48: data = 16'h127a;
      10'd49: data = 16'h1249;
      10'd50: data = 16'h121a;
      10'd51: data = 16'h11ec;
      10'd52: data = 16'h11c0;
      10'd53: data = 16'h1195;
      10'd54: data = 16'h116b;
      10'd55: data = 16'h1142;
      10'd56: data = 16'h111b;
      10'd57: data = 16'h10f4;
      10'd58: data = 16'h10cf;
      10'd59: data = 16'h10aa;
      10'd60: data = 16'h1086;
      10'd61: data = 16'h1064;
      10'd62: data = 16'h1042;
      10'd63: data = 16'h1020;
      10'd64: data = 16'h1000;
      10'd65: data = 16'hfe0;
      10'd66: data = 16'hfc1;
      10'd67: data = 16'hfa3;
      10'd68: data = 16'hf86;
      10'd69: data = 16'hf69;
      10'd70: data = 16'hf4d;
      10'd71: data = 16'hf31;
      10'd72: data = 16'hf16;
      10'd73: data = 16'hefb;
      10'd74: data = 16'hee1;
      10'd75: data = 16'hec8;
      10'd76: data = 16'heaf;
      10'd77: data = 16'he96;
      10'd78: data = 16'he7e;
      10'd79: data = 16'he67;
      10'd80: data = 16'he50;
      10'd81: data = 16'he39;
      10'd82: data = 16'he23;
      10'd83: data = 16'he0d;
      10'd84: data = 16'hdf7;
      10'd85: data = 16'hde2;
      10'd86: data = 16'hdcd;
      10'd87: data = 16'hdb9;
      10'd88: data = 16'hda5;
      10'd89: data = 16'hd91;
      10'd90: data = 16'hd7e;
      10'd91: data = 16'hd6b;
      10'd92: data = 16'hd58;
      10'd93: data = 16'hd46;
      10'd94: data = 16'hd34;
      10'd95: data = 16'hd22;
      10'd96: data = 16'hd10;
      10'd97: data = 16'hcff;
      10'd98: data = 16'hcee;
      10'd99: data = 16'hcdd;
      10'd100: data = 16'hccd;
      10'd101: data = 16'hcbd;
      10'd102: data = 16'hcad;
      10'd103: data = 16'hc9d;
      10'd104: data = 16'hc8d;
      10'd105: data = 16'hc7e;
      10'd106: data = 16'hc6f;
      10'd107: data = 16'hc60;
      10'd108: data = 16'hc51;
      10'd109: data = 16'hc43;
      10'd110: data = 16'hc34;
      10'd111: data = 16'hc26;
      10'd112: data = 16'hc18;
      10'd113: data = 16'hc0b;
      10'd114: data = 16'hbfd;
      10'd115: data = 16'hbf0;
      10'd116: data = 16'hbe2;
      10'd117: data = 16'hbd5;
      10'd118: data = 16'hbc9;
      10'd119: data = 16'hbbc;
      10'd120: data = 16'hbaf;
      10'd121: data = 16'hba3;
      10'd122: data = 16'hb97;
      10'd123: data = 16'hb8b;
      10'd124: data = 16'hb7f;
      10'd125: data = 16'hb73;
      10'd126: data = 16'hb67;
      10'd127: data = 16'hb5c;
      10'd128: data = 16'hb50;
      10'd129: data = 16'hb45;
      10'd130: data = 16'hb3a;
      10'd131: data = 16'hb2f;
      10'd132: data = 16'hb24;
      10'd133: data = 16'hb19;
      10'd134: data = 16'hb0f;
      10'd135: data = 16'hb04;
      10'd136: data = 16'hafa;
      10'd137: data = 16'haf0;
      10'd138: data = 16'hae5;
      10'd139: data = 16'hadb;
      10'd140: data = 16'had1;
      10'd141: data = 16'hac8;
      10'd142: data = 16'habe;
      10'd143: data = 16'hab4;
      10'd144: data = 16'haab;
      10'd145: data = 16'haa1;
      10'd146: data = 16'ha98;
      10'd147: data = 16'ha8f;
      10'd148: data = 16'ha86;
      10'd149: data = 16'ha7c;
      10'd150: data = 16'ha73;
      10'd151: data = 16'ha6b;
      10'd152: data = 16'ha62;
      10'd153: data = 16'ha59;
      10'd154: data = 16'ha51;
      10'd155: data = 16'ha48;
      10'd156: data = 16'ha40;
      10'd157: data = 16'ha37;
      10'd158: data = 16'ha2f;
      10'd159: data = 16'ha27;
      10'd160: data = 16'ha1f;
      10'd161: data = 16'ha16;
      10'd162: data = 16'ha0e;
      10'd163: data = 16'ha07;
      10'd164: data = 16'h9ff;
      10'd165: data = 16'h9f7;
      10'd166: data = 16'h9ef;
      10'd167: data = 16'h9e8;
      10'd168: data = 16'h9e0;
      10'd169: data = 16'h9d9;
      10'd170: data = 16'h9d1;
      10'd171: data = 16'h9ca;
      10'd172: data = 16'h9c3;
      10'd173: data = 16'h9bb;
      10'd174: data = 16'h9b4;
      10'd175: data = 16'h9ad;
      10'd176: data = 16'h9a6;
      10'd177: data = 16'h99f;
      10'd178: data = 16'h998;
      10'd179: data = 16'h991;
      10'd180: data = 16'h98a;
      10'd181: data = 16'h984;
      10'd182: data = 16'h97d;
      10'd183: data = 16'h976;
      10'd184: data = 16'h970;
      10'd185: data = 16'h969;
      10'd186: data = 16'h963;
      10'd187: data = 16'h95c;
      10'd188: data = 16'h956;
      10'd189: data = 16'h950;
      10'd190: data = 16'h949;
      10'd191: data = 16'h943;
      10'd192: data = 16'h93d;
      10'd193: data = 16'h937;
      10'd194: data = 16'h931;
      10'd195: data = 16'h92b;
      10'd196: data = 16'h925;
      10'd197: data = 16'h91f;
      10'd198: data = 16'h919;
      10'd199: data = 16'h913;
      10'd200: data = 16'h90d;
      10'd201: data = 16'h907;
      10'd202: data = 16'h902;
      10'd203: data = 16'h8fc;
      10'd204: data = 16'h8f6;
      10'd205: data = 16'h8f1;
      10'd206: data = 16'h8eb;
      10'd207: data = 16'h8e6;
      10'd208: data = 16'h8e0;
      10'd209: data = 16'h8db;
      10'd210: data = 16'h8d5;
      10'd211: data = 16'h8d0;
      10'd212: data = 16'h8cb;
      10'd213: data = 16'h8c5;
      10'd214: data = 16'h8c0;
      10'd215: data = 16'h8bb;
      10'd216: data = 16'h8b6;
      10'd217: data = 16'h8b0;
      10'd218: data = 16'h8ab;
      10'd219: data = 16'h8a6;
      10'd220: data = 16'h8a1;
      10'd221: data = 16'h89c;
      10'd222: data = 16'h897;
      10'd223: data = 16'h892;
      10'd224: data = 16'h88d;
      10'd225: data = 16'h889;
      10'd226: data = 16'h884;
      10'd227: data = 16'h87f;
      10'd228: data = 16'h87a;
      10'd229: data = 16'h875;
      10'd230: data = 16'h871;
      10'd231: data = 16'h86c;
      10'd232: data = 16'h867;
      10'd233: data = 16'h863;
      10'd234: data = 16'h85e;
      10'd235: data = 16'h85a;
      10'd236: data = 16'h855;
      10'd237: data = 16'h851;
      10'd238: data = 16'h84c;
      10'd239: data = 16'h848;
      10'd240: data = 16'h843;
      10'd241: data = 16'h83f;
      10'd242: data = 16'h83a;
      10'd243: data = 16'h836;
      10'd244: data = 16'h832;
      10'd245: data = 16'h82d;
      10'd246: data = 16'h829;
      10'd247: data = 16'h825;
      10'd248: data = 16'h821;
      10'd249: data = 16'h81d;
      10'd250: data = 16'h818;
      10'd251: data = 16'h814;
      10'd252: data = 16'h810;
      10'd253: data = 16'h80c;
      10'd254: data = 16'h808;
      10'd255: data = 16'h804;
      10'd256: data = 16'h800;
      10'd257: data = 16'h7fc;
      10'd258: data = 16'h7f8;
      10'd259: data = 16'h7f4;
      10'd260: data = 16'h7f0;
      10'd261: data = 16'h7ec;
      10'd262: data = 16'h7e8;
      10'd263: data = 16'h7e5;
      10'd264: data = 16'h7e1;
      10'd265: data = 16'h7dd;
      10'd266: data = 16'h7d9;
      10'd267: data = 16'h7d5;
      10'd268: data = 16'h7d2;
      10'd269: data = 16'h7ce;
      10'd270: data = 16'h7ca;
      10'd271: data = 16'h7c7;
      10'd272: data = 16'h7c3;
      10'd273: data = 16'h7bf;
      10'd274: data = 16'h7bc;
      10'd275: data = 16'h7b8;
      10'd276: data = 16'h7b4;
      10'd277: data = 16'h7b1;
      10'd278: data = 16'h7ad;
      10'd279: data = 16'h7aa;
      10'd280: data = 16'h7a6;
      10'd281: data = 16'h7a3;
      10'd282: data = 16'h79f;
      10'd283: data = 16'h79c;
      10'd284: data = 16'h798;
      10'd285: data = 16'h795;
      10'd286: data = 16'h792;
      10'd287: data = 16'h78e;
      10'd288: data = 16'h78b;
      10'd289: data = 16'h788;
      10'd290: data = 16'h784;
      10'd291: data = 16'h781;
      10'd292: data = 16'h77e;
      10'd293: data = 16'h77a;
      10'd294: data = 16'h777;
      10'd295: data = 16'h774;
      10'd296: data = 16'h771;
      10'd297: data = 16'h76d;
      10'd298: data = 16'h76a;
      10'd299: data = 16'h767;
      10'd300: data = 16'h764;
      10'd301: data = 16'h761;
      10'd302: data = 16'h75e;
      10'd303: data = 16'h75a;
      10'd304: data = 16'h757;
      10'd305: data = 16'h754;
      10'd306: data = 16'h751;
      10'd307: data = 16'h74e;
      10'd308: data = 16'h74b;
      10'd309: data = 16'h748;
      10'd310: data = 16'h745;
      10'd311: data = 16'h742;
      10'd312: data = 16'h73f;
      10'd313: data = 16'h73c;
      10'd314: data = 16'h739;
      10'd315: data = 16'h736;
      10'd316: data = 16'h733;
      10'd317: data = 16'h730;
      10'd318: data = 16'h72e;
      10'd319: data = 16'h72b;
      10'd320: data = 16'h728;
      10'd321: data = 16'h725;
      10'd322: data = 16'h722;
      10'd323: data = 16'h71f;
      10'd324: data = 16'h71c;
      10'd325: data = 16'h71a;
      10'd326: data = 16'h717;
      10'd327: data = 16'h714;
      10'd328: data = 16'h711;
      10'd329: data = 16'h70f;
      10'd330: data = 16'h70c;
      10'd331: data = 16'h709;
      10'd332: data = 16'h706;
      10'd333: data = 16'h704;
      10'd334: data = 16'h701;
      10'd335: data = 16'h6fe;
      10'd336: data = 16'h6fc;
      10'd337: data = 16'h6f9;
      10'd338: data = 16'h6f6;
      10'd339: data = 16'h6f4;
      10'd340: data = 16'h6f1;
      10'd341: data = 16'h6ee;
      10'd342: data = 16'h6ec;
      10'd343: data = 16'h6e9;
      10'd344: data = 16'h6e7;
      10'd345: data = 16'h6e4;
      10'd346: data = 16'h6e2;
      10'd347: data = 16'h6df;
      10'd348: data = 16'h6dd;
      10'd349: data = 16'h6da;
      10'd350: data = 16'h6d8;
      10'd351: data = 16'h6d5;
      10'd352: data = 16'h6d3;
      10'd353: data = 16'h6d0;
      10'd354: data = 16'h6ce;
      10'd355: data = 16'h6cb;
      10'd356: data = 16'h6c9;
      10'd357: data = 16'h6c6;
      10'd358: data = 16'h6c4;
      10'd359: data = 16'h6c1;
      10'd360: data = 16'h6bf;
      10'd361: data = 16'h6bd;
      10'd362: data = 16'h6ba;
      10'd363: data = 16'h6b8;
      10'd364: data = 16'h6b6;
      10'd365: data = 16'h6b3;
      10'd366: data = 16'h6b1;
      10'd367: data = 16'h6ae;
      10'd368: data = 16'h6ac;
      10'd369: data = 16'h6aa;
      10'd370: data = 16'h6a8;
      10'd371: data = 16'h6a5;
      10'd372: data = 16'h6a3;
      10'd373: data = 16'h6a1;
      10'd374: data = 16'h69e;
      10'd375: data = 16'h69c;
      10'd376: data = 16'h69a;
      10'd377: data = 16'h698;
      10'd378: data = 16'h695;
      10'd379: data = 16'h693;
      10'd380: data = 16'h691;
      10'd381: data = 16'h68f;
      10'd382: data = 16'h68d;
      10'd383: data = 16'h68a;
      10'd384: data = 16'h688;
      10'd385: data = 16'h686;
      10'd386: data = 16'h684;
      10'd387: data = 16'h682;
      10'd388: data = 16'h680;
      10'd389: data = 16'h67d;
      10'd390: data = 16'h67b;
      10'd391: data = 16'h679;
      10'd392: data = 16'h677;
      10'd393: data = 16'h675;
      10'd394: data = 16'h673;
      10'd395: data = 16'h671;
      10'd396: data = 16'h66f;
      10'd397: data = 16'h66d;
      10'd398: data = 16'h66b;
      10'd399: data = 16'h668;
      10'd400: data = 16'h666;
      10'd401: data = 16'h664;
      10'd402: data = 16'h662;
      10'd403: data = 16'h660;
      10'd404: data = 16'h65e;
      10'd405: data = 16'h65c;
      10'd406: data = 16'h65a;
      10'd407: data = 16'h658;
      10'd408: data = 16'h656;
      10'd409: data = 16'h654;
      10'd410: data = 16'h652;
      10'd411: data = 16'h650;
      10'd412: data = 16'h64e;
      10'd413: data = 16'h64c;
      10'd414: data = 16'h64a;
      10'd415: data = 16'h649;
      10'd416: data = 16'h647;
      10'd417: data = 16'h645;
      10'd418: data = 16'h643;
      10'd419: data = 16'h641;
      10'd420: data = 16'h63f;
      10'd421: data = 16'h63d;
      10'd422: data = 16'h63b;
      10'd423: data = 16'h639;
      10'd424: data = 16'h637;
      10'd425: data = 16'h635;
      10'd426: data = 16'h634;
      10'd427: data = 16'h632;
      10'd428: data = 16'h630;
      10'd429: data = 16'h62e;
      10'd430: data = 16'h62c;
      10'd431: data = 16'h62a;
      10'd432: data = 16'h629;
      10'd433: data = 16'h627;
      10'd434: data = 16'h625;
      10'd435: data = 16'h623;
      10'd436: data = 16'h621;
      10'd437: data = 16'h620;
      10'd438: data = 16'h61e;
      10'd439: data = 16'h61c;
      10'd440: data = 16'h61a;
      10'd441: data = 16'h618;
      10'd442: data = 16'h617;
      10'd443: data = 16'h615;
      10'd444: data = 16'h613;
      10'd445: data = 16'h611;
      10'd446: data = 16'h610;
      10'd447: data = 16'h60e;
      10'd448: data = 16'h60c;
      10'd449: data = 16'h60a;
      10'd450: data = 16'h609;
      10'd451: data = 16'h607;
      10'd452: data = 16'h605;
      10'd453: data = 16'h604;
      10'd454: data = 16'h602;
      10'd455: data = 16'h600;
      10'd456: data = 16'h5ff;
      10'd457: data = 16'h5fd;
      10'd458: data = 16'h5fb;
      10'd459: data = 16'h5f9;
      10'd460: data = 16'h5f8;
      10'd461: data = 16'h5f6;
      10'd462: data = 16'h5f5;
      10'd463: data = 16'h5f3;
      10'd464: data = 16'h5f1;
      10'd465: data = 16'h5f0;
      10'd466: data = 16'h5ee;
      10'd467: data = 16'h5ec;
      10'd468: data = 16'h5eb;
      10'd469: data = 16'h5e9;
      10'd470: data = 16'h5e7;
      10'd471: data = 16'h5e6;
      10'd472: data = 16'h5e4;
      10'd473: data = 16'h5e3;
      10'd474: data = 16'h5e1;
      10'd475: data = 16'h5df;
      10'd476: data = 16'h5de;
      10'd477: data = 16'h5dc;
      10'd478: data = 16'h5db;
      10'd479: data = 16'h5d9;
      10'd480: data = 16'h5d8;
      10'd481: data = 16'h5d6;
      10'd482: data = 16'h5d5;
      10'd483: data = 16'h5d3;
      10'd484: data = 16'h5d1;
      10'd485: data = 16'h5d0;
      10'd486: data = 16'h5ce;
      10'd487: data = 16'h5cd;
      10'd488: data = 16'h5cb;
      10'd489: data = 16'h5ca;
      10'd490: data = 16'h5c8;
      10'd491: data = 16'h5c7;
      10'd492: data = 16'h5c5;
      10'd493: data = 16'h5c4;
      10'd494: data = 16'h5c2;
      10'd495: data = 16'h5c1;
      10'd496: data = 16'h5bf;
      10'd497: data = 16'h5be;
      10'd498: data = 16'h5bc;
      10'd499: data = 16'h5bb;
      10'd500: data = 16'h5b9;
      10'd501: data = 16'h5b8;
      10'd502: data = 16'h5b7;
      10'd503: data = 16'h5b5;
      10'd504: data = 16'h5b4;
      10'd505: data = 16'h5b2;
      10'd506: data = 16'h5b1;
      10'd507: data = 16'h5af;
      10'd508: data = 16'h5ae;
      10'd509: data = 16'h5ac;
      10'd510: data = 16'h5ab;
      10'd511: data = 16'h5aa;
      10'd512: data = 16'h5a8;
      10'd513: data = 16'h5a7;
      10'd514: data = 16'h5a5;
      10'd515: data = 16'h5a4;
      10'd516: data = 16'h5a3;
      10'd517: data = 16'h5a1;
      10'd518: data = 16'h5a0;
      10'd519: data = 16'h59e;
      10'd520: data = 16'h59d;
      10'd521: data = 16'h59c;
      10'd522: data = 16'h59a;
      10'd523: data = 16'h599;
      10'd524: data = 16'h597;
      10'd525: data = 16'h596;
      10'd526: data = 16'h595;
      10'd527: data = 16'h593;
      10'd528: data = 16'h592;
      10'd529: data = 16'h591;
      10'd530: data = 16'h58f;
      10'd531: data = 16'h58e;
      10'd532: data = 16'h58d;
      10'd533: data = 16'h58b;
      10'd534: data = 16'h58a;
      10'd535: data = 16'h589;
      10'd536: data = 16'h587;
      10'd537: data = 16'h586;
      10'd538: data = 16'h585;
      10'd539: data = 16'h583;
      10'd540: data = 16'h582;
      10'd541: data = 16'h581;
      10'd542: data = 16'h580;
      10'd543: data = 16'h57e;
      10'd544: data = 16'h57d;
      10'd545: data = 16'h57c;
      10'd546: data = 16'h57a;
      10'd547: data = 16'h579;
      10'd548: data = 16'h578;
      10'd549: data = 16'h577;
      10'd550: data = 16'h575;
      10'd551: data = 16'h574;
      10'd552: data = 16'h573;
      10'd553: data = 16'h571;
      10'd554: data = 16'h570;
      10'd555: data = 16'h56f;
      10'd556: data = 16'h56e;
      10'd557: data = 16'h56c;
      10'd558: data = 16'h56b;
      10'd559: data = 16'h56a;
      10'd560: data = 16'h569;
      10'd561: data = 16'h567;
      10'd562: data = 16'h566;
      10'd563: data = 16'h565;
      10'd564: data = 16'h564;
      10'd565: data = 16'h563;
      10'd566: data = 16'h561;
      10'd567: data = 16'h560;
      10'd568: data = 16'h55f;
      10'd569: data = 16'h55e;
      10'd570: data = 16'h55d;
      10'd571: data = 16'h55b;
      10'd572: data = 16'h55a;
      10'd573: data = 16'h559;
      10'd574: data = 16'h558;
      10'd575: data = 16'h557;
      10'd576: data = 16'h555;
      10'd577: data = 16'h554;
      10'd578: data = 16'h553;
      10'd579: data = 16'h552;
      10'd580: data = 16'h551;
      10'd581: data = 16'h54f;
      10'd582: data = 16'h54e;
      10'd583: data = 16'h54d;
      10'd584: data = 16'h54c;
      10'd585: data = 16'h54b;
      10'd586: data = 16'h54a;
      10'd587: data = 16'h548;
      10'd588: data = 16'h547;
      10'd589: data = 16'h546;
      10'd590: data = 16'h545;
      10'd591: data = 16'h544;
      10'd592: data = 16'h543;
      10'd593: data = 16'h542;
      10'd594: data = 16'h540;
      10'd595: data = 16'h53f;
      10'd596: data = 16'h53e;
      10'd597: data = 16'h53d;
      10'd598: data = 16'h53c;
      10'd599: data = 16'h53b;
      10'd600: data = 16'h53a;
      10'd601: data = 16'h539;
      10'd602: data = 16'h538;
      10'd603: data = 16'h536;
      10'd604: data = 16'h535;
      10'd605: data = 16'h534;
      10'd606: data = 16'h533;
      10'd607: data = 16'h532;
      10'd608: data = 16'h531;
      10'd609: data = 16'h530;
      10'd610: data = 16'h52f;
      10'd611: data = 16'h52e;
      10'd612: data = 16'h52d;
      10'd613: data = 16'h52b;
      10'd614: data = 16'h52a;
      10'd615: data = 16'h529;
      10'd616: data = 16'h528;
      10'd617: data = 16'h527;
      10'd618: data = 16'h526;
      10'd619: data = 16'h525;
      10'd620: data = 16'h524;
      10'd621: data = 16'h523;
      10'd622: data = 16'h522;
      10'd623: data = 16'h521;
      10'd624: data = 16'h520;
      10'd625: data = 16'h51f;
      10'd626: data = 16'h51e;
      10'd627: data = 16'h51d;
      10'd628: data = 16'h51c;
      10'd629: data = 16'h51b;
      10'd630: data = 16'h51a;
      10'd631: data = 16'h518;
      10'd632: data = 16'h517;
      10'd633: data = 16'h516;
      10'd634: data = 16'h515;
      10'd635: data = 16'h514;
      10'd636: data = 16'h513;
      10'd637: data = 16'h512;
      10'd638: data = 16'h511;
      10'd639: data = 16'h510;
      10'd640: data = 16'h50f;
      10'd641: data = 16'h50e;
      10'd642: data = 16'h50d;
      10'd643: data = 16'h50c;
      10'd644: data = 16'h50b;
      10'd645: data = 16'h50a;
      10'd646: data = 16'h509;
      10'd647: data = 16'h508;
      10'd648: data = 16'h507;
      10'd649: data = 16'h506;
      10'd650: data = 16'h505;
      10'd651: data = 16'h504;
      10'd652: data = 16'h503;
      10'd653: data = 16'h502;
      10'd654: data = 16'h501;
      10'd655: data = 16'h500;
      10'd656: data = 16'h4ff;
      10'd657: data = 16'h4fe;
      10'd658: data = 16'h4fd;
      10'd659: data = 16'h4fc;
      10'd660: data = 16'h4fb;
      10'd661: data = 16'h4fb;
      10'd662: data = 16'h4fa;
      10'd663: data = 16'h4f9;
      10'd664: data = 16'h4f8;
      10'd665: data = 16'h4f7;
      10'd666: data = 16'h4f6;
      10'd667: data = 16'h4f5;
      10'd668: data = 16'h4f4;
      10'd669: data = 16'h4f3;
      10'd670: data = 16'h4f2;
      10'd671: data = 16'h4f1;
      10'd672: data = 16'h4f0;
      10'd673: data = 16'h4ef;
      10'd674: data = 16'h4ee;
      10'd675: data = 16'h4ed;
      10'd676: data = 16'h4ec;
      10'd677: data = 16'h4eb;
      10'd678: data = 16'h4ea;
      10'd679: data = 16'h4ea;
      10'd680: data = 16'h4e9;
      10'd681: data = 16'h4e8;
      10'd682: data = 16'h4e7;
      10'd683: data = 16'h4e6;
      10'd684: data = 16'h4e5;
      10'd685: data = 16'h4e4;
      10'd686: data = 16'h4e3;
      10'd687: data = 16'h4e2;
      10'd688: data = 16'h4e1;
      10'd689: data = 16'h4e0;
      10'd690: data = 16'h4df;
      10'd691: data = 16'h4df;
      10'd692: data = 16'h4de;
      10'd693: data = 16'h4dd;
      10'd694: data = 16'h4dc;
      10'd695: data = 16'h4db;
      10'd696: data = 16'h4da;
      10'd697: data = 16'h4d9;
      10'd698: data = 16'h4d8;
      10'd699: data = 16'h4d7;
      10'd700: data = 16'h4d7;
      10'd701: data = 16'h4d6;
      10'd702: data = 16'h4d5;
      10'd703: data = 16'h4d4;
      10'd704: data = 16'h4d3;
      10'd705: data = 16'h4d2;
      10'd706: data = 16'h4d1;
      10'd707: data = 16'h4d0;
      10'd708: data = 16'h4cf;
      10'd709: data = 16'h4cf;
      10'd710: data = 16'h4ce;
      10'd711: data = 16'h4cd;
      10'd712: data = 16'h4cc;
      10'd713: data = 16'h4cb;
      10'd714: data = 16'h4ca;
      10'd715: data = 16'h4c9;
      10'd716: data = 16'h4c9;
      10'd717: data = 16'h4c8;
      10'd718: data = 16'h4c7;
      10'd719: data = 16'h4c6;
      10'd720: data = 16'h4c5;
      10'd721: data = 16'h4c4;
      10'd722: data = 16'h4c3;
      10'd723: data = 16'h4c3;
      10'd724: data = 16'h4c2;
      10'd725: data = 16'h4c1;
      10'd726: data = 16'h4c0;
      10'd727: data = 16'h4bf;
      10'd728: data = 16'h4be;
      10'd729: data = 16'h4be;
      10'd730: data = 16'h4bd;
      10'd731: data = 16'h4bc;
      10'd732: data = 16'h4bb;
      10'd733: data = 16'h4ba;
      10'd734: data = 16'h4b9;
      10'd735: data = 16'h4b9;
      10'd736: data = 16'h4b8;
      10'd737: data = 16'h4b7;
      10'd738: data = 16'h4b6;
      10'd739: data = 16'h4b5;
      10'd740: data = 16'h4b5;
      10'd741: data = 16'h4b4;
      10'd742: data = 16'h4b3;
      10'd743: data = 16'h4b2;
      10'd744: data = 16'h4b1;
      10'd745: data = 16'h4b1;
      10'd746: data = 16'h4b0;
      10'd747: data = 16'h4af;
      10'd748: data = 16'h4ae;
      10'd749: data = 16'h4ad;
      10'd750: data = 16'h4ad;
      10'd751: data = 16'h4ac;
      10'd752: data = 16'h4ab;
      10'd753: data = 16'h4aa;
      10'd754: data = 16'h4a9;
      10'd755: data = 16'h4a9;
      10'd756: data = 16'h4a8;
      10'd757: data = 16'h4a7;
      10'd758: data = 16'h4a6;
      10'd759: data = 16'h4a5;
      10'd760: data = 16'h4a5;
      10'd761: data = 16'h4a4;
      10'd762: data = 16'h4a3;
      10'd763: data = 16'h4a2;
      10'd764: data = 16'h4a2;
      10'd765: data = 16'h4a1;
      10'd766: data = 16'h4a0;
      10'd767: data = 16'h49f;
      10'd768: data = 16'h49e;
      10'd769: data = 16'h49e;
      10'd770: data = 16'h49d;
      10'd771: data = 16'h49c;
      10'd772: data = 16'h49b;
      10'd773: data = 16'h49b;
      10'd774: data = 16'h49a;
      10'd775: data = 16'h499;
      10'd776: data = 16'h498;
      10'd777: data = 16'h498;
      10'd778: data = 16'h497;
      10'd779: data = 16'h496;
      10'd780: data = 16'h495;
      10'd781: data = 16'h495;
      10'd782: data = 16'h494;
      10'd783: data = 16'h493;
      10'd784: data = 16'h492;
      10'd785: data = 16'h492;
      10'd786: data = 16'h491;
      10'd787: data = 16'h490;
      10'd788: data = 16'h48f;
      10'd789: data = 16'h48f;
      10'd790: data = 16'h48e;
      10'd791: data = 16'h48d;
      10'd792: data = 16'h48c;
      10'd793: data = 16'h48c;
      10'd794: data = 16'h48b;
      10'd795: data = 16'h48a;
      10'd796: data = 16'h489;
      10'd797: data = 16'h489;
      10'd798: data = 16'h488;
      10'd799: data = 16'h487;
      10'd800: data = 16'h487;
      10'd801: data = 16'h486;
      10'd802: data = 16'h485;
      10'd803: data = 16'h484;
      10'd804: data = 16'h484;
      10'd805: data = 16'h483;
      10'd806: data = 16'h482;
      10'd807: data = 16'h481;
      10'd808: data = 16'h481;
      10'd809: data = 16'h480;
      10'd810: data = 16'h47f;
      10'd811: data = 16'h47f;
      10'd812: data = 16'h47e;
      10'd813: data = 16'h47d;
      10'd814: data = 16'h47d;
      10'd815: data = 16'h47c;
      10'd816: data = 16'h47b;
      10'd817: data = 16'h47a;
      10'd818: data = 16'h47a;
      10'd819: data = 16'h479;
      10'd820: data = 16'h478;
      10'd821: data = 16'h478;
      10'd822: data = 16'h477;
      10'd823: data = 16'h476;
      10'd824: data = 16'h476;
      10'd825: data = 16'h475;
      10'd826: data = 16'h474;
      10'd827: data = 16'h473;
      10'd828: data = 16'h473;
      10'd829: data = 16'h472;
      10'd830: data = 16'h471;
      10'd831: data = 16'h471;
      10'd832: data = 16'h470;
      10'd833: data = 16'h46f;
      10'd834: data = 16'h46f;
      10'd835: data = 16'h46e;
      10'd836: data = 16'h46d;
      10'd837: data = 16'h46d;
      10'd838: data = 16'h46c;
      10'd839: data = 16'h46b;
      10'd840: data = 16'h46b;
      10'd841: data = 16'h46a;
      10'd842: data = 16'h469;
      10'd843: data = 16'h469;
      10'd844: data = 16'h468;
      10'd845: data = 16'h467;
      10'd846: data = 16'h467;
      10'd847: data = 16'h466;
      10'd848: data = 16'h465;
      10'd849: data = 16'h465;
      10'd850: data = 16'h464;
      10'd851: data = 16'h463;
      10'd852: data = 16'h463;
      10'd853: data = 16'h462;
      10'd854: data = 16'h461;
      10'd855: data = 16'h461;
      10'd856: data = 16'h460;
      10'd857: data = 16'h45f;
      10'd858: data = 16'h45f;
      10'd859: data = 16'h45e;
      10'd860: data = 16'h45d;
      10'd861: data = 16'h45d;
      10'd862: data = 16'h45c;
      10'd863: data = 16'h45b;
      10'd864: data = 16'h45b;
      10'd865: data = 16'h45a;
      10'd866: data = 16'h45a;
      10'd867: data = 16'h459;
      10'd868: data = 16'h458;
      10'd869: data = 16'h458;
      10'd870: data = 16'h457;
      10'd871: data = 16'h456;
      10'd872: data = 16'h456;
      10'd873: data = 16'h455;
      10'd874: data = 16'h454;
      10'd875: data = 16'h454;
      10'd876: data = 16'h453;
      10'd877: data = 16'h452;
      10'd878: data = 16'h452;
      10'd879: data = 16'h451;
      10'd880: data = 16'h451;
      10'd881: data = 16'h450;
      10'd882: data = 16'h44f;
      10'd883: data = 16'h44f;
      10'd884: data = 16'h44e;
      10'd885: data = 16'h44d;
      10'd886: data = 16'h44d;
      10'd887: data = 16'h44c;
      10'd888: data = 16'h44c;
      10'd889: data = 16'h44b;
      10'd890: data = 16'h44a;
      10'd891: data = 16'h44a;
      10'd892: data = 16'h449;
      10'd893: data = 16'h449;
      10'd894: data = 16'h448;
      10'd895: data = 16'h447;
      10'd896: data = 16'h447;
      10'd897: data = 16'h446;
      10'd898: data = 16'h445;
      10'd899: data = 16'h445;
      10'd900: data = 16'h444;
      10'd901: data = 16'h444;
      10'd902: data = 16'h443;
      10'd903: data = 16'h442;
      10'd904: data = 16'h442;
      10'd905: data = 16'h441;
      10'd906: data = 16'h441;
      10'd907: data = 16'h440;
      10'd908: data = 16'h43f;
      10'd909: data = 16'h43f;
      10'd910: data = 16'h43e;
      10'd911: data = 16'h43e;
      10'd912: data = 16'h43d;
      10'd913: data = 16'h43c;
      10'd914: data = 16'h43c;
      10'd915: data = 16'h43b;
      10'd916: data = 16'h43b;
      10'd917: data = 16'h43a;
      10'd918: data = 16'h43a;
      10'd919: data = 16'h439;
      10'd920: data = 16'h438;
      10'd921: data = 16'h438;
      10'd922: data = 16'h437;
      10'd923: data = 16'h437;
      10'd924: data = 16'h436;
      10'd925: data = 16'h435;
      10'd926: data = 16'h435;
      10'd927: data = 16'h434;
      10'd928: data = 16'h434;
      10'd929: data = 16'h433;
      10'd930: data = 16'h433;
      10'd931: data = 16'h432;
      10'd932: data = 16'h431;
      10'd933: data = 16'h431;
      10'd934: data = 16'h430;
      10'd935: data = 16'h430;
      10'd936: data = 16'h42f;
      10'd937: data = 16'h42e;
      10'd938: data = 16'h42e;
      10'd939: data = 16'h42d;
      10'd940: data = 16'h42d;
      10'd941: data = 16'h42c;
      10'd942: data = 16'h42c;
      10'd943: data = 16'h42b;
      10'd944: data = 16'h42b;
      10'd945: data = 16'h42a;
      10'd946: data = 16'h429;
      10'd947: data = 16'h429;
      10'd948: data = 16'h428;
      10'd949: data = 16'h428;
      10'd950: data = 16'h427;
      10'd951: data = 16'h427;
      10'd952: data = 16'h426;
      10'd953: data = 16'h425;
      10'd954: data = 16'h425;
      10'd955: data = 16'h424;
      10'd956: data = 16'h424;
      10'd957: data = 16'h423;
      10'd958: data = 16'h423;
      10'd959: data = 16'h422;
      10'd960: data = 16'h422;
      10'd961: data = 16'h421;
      10'd962: data = 16'h420;
      10'd963: data = 16'h420;
      10'd964: data = 16'h41f;
      10'd965: data = 16'h41f;
      10'd966: data = 16'h41e;
      10'd967: data = 16'h41e;
      10'd968: data = 16'h41d;
      10'd969: data = 16'h41d;
      10'd970: data = 16'h41c;
      10'd971: data = 16'h41c;
      10'd972: data = 16'h41b;
      10'd973: data = 16'h41a;
      10'd974: data = 16'h41a;
      10'd975: data = 16'h419;
      10'd976: data = 16'h419;
      10'd977: data = 16'h418;
      10'd978: data = 16'h418;
      10'd979: data = 16'h417;
      10'd980: data = 16'h417;
      10'd981: data = 16'h416;
      10'd982: data = 16'h416;
      10'd983: data = 16'h415;
      10'd984: data = 16'h415;
      10'd985: data = 16'h414;
      10'd986: data = 16'h414;
      10'd987: data = 16'h413;
      10'd988: data = 16'h412;
      10'd989: data = 16'h412;
      10'd990: data = 16'h411;
      10'd991: data = 16'h411;
      10'd992: data = 16'h410;
      10'd993: data = 16'h410;
      10'd994: data = 16'h40f;
      10'd995: data = 16'h40f;
      10'd996: data = 16'h40e;
      10'd997: data = 16'h40e;
      10'd998: data = 16'h40d;
      10'd999: data = 16'h40d;
      10'd1000: data = 16'h40c;
      10'd1001: data = 16'h40c;
      10'd1002: data = 16'h40b;
      10'd1003: data = 16'h40b;
      10'd1004: data = 16'h40a;
      10'd1005: data = 16'h40a;
      10'd1006: data = 16'h409;
      10'd1007: data = 16'h409;
      10'd1008: data = 16'h408;
      10'd1009: data = 16'h408;
      10'd1010: data = 16'h407;
      10'd1011: data = 16'h407;
      10'd1012: data = 16'h406;
      10'd1013: data = 16'h406;
      10'd1014: data = 16'h405;
      10'd1015: data = 16'h405;
      10'd1016: data = 16'h404;
      10'd1017: data = 16'h404;
      10'd1018: data = 16'h403;
      10'd1019: data = 16'h403;
      10'd1020: data = 16'h402;
      10'd1021: data = 16'h402;
      10'd1022: data = 16'h401;
      10'd1023: data = 16'h401;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$1$lighting$rnorm
module top$pipeline$shade$1$lighting$sh_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sh_q$0
module top$pipeline$shade$1$lighting$sh_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sh_q$1
module top$pipeline$shade$1$lighting$sh_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sh_q$2
module top$pipeline$shade$1$lighting$sl_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sl_q$0
module top$pipeline$shade$1$lighting$sl_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sl_q$1
module top$pipeline$shade$1$lighting$sl_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$sl_q$2
module top$pipeline$shade$1$lighting$specular_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$specular_q
module top$pipeline$shade$1$lighting$specular_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h31000;
    localparam  window = 24'h31400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$specular_table$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lighting$specular_table
module top$pipeline$shade$1$lighting$specular_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lighting$specular_table$ram
module top$pipeline$shade$1$lighting$square$0(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$1$lighting$square$0
module top$pipeline$shade$1$lighting$square$1(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$1$lighting$square$1
module top$pipeline$shade$1$lighting$square$2(address,data);
    
    // Module arguments
    input wire  [6:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address[3:0])
      4'd0: data = 16'h0;
      4'd1: data = 16'h1;
      4'd2: data = 16'h4;
      4'd3: data = 16'h9;
      4'd4: data = 16'h10;
      4'd5: data = 16'h19;
      4'd6: data = 16'h24;
      4'd7: data = 16'h31;
      4'd8: data = 16'h40;
      4'd9: data = 16'h51;
      4'd10: data = 16'h64;
      4'd11: data = 16'h79;
      4'd12: data = 16'h90;
      4'd13: data = 16'ha9;
      4'd14: data = 16'hc4;
      4'd15: data = 16'he1;
      default: data = 16'h0;
    endcase
endmodule // top$pipeline$shade$1$lighting$square$2
module top$pipeline$shade$1$lighting$t_h(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$t_h
module top$pipeline$shade$1$lighting$t_l(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lighting$t_l
module top$pipeline$shade$1$lighting$third_h(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$third_h
module top$pipeline$shade$1$lighting$third_l(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$third_l
module top$pipeline$shade$1$lighting$u_h(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= 'h0;
    end
endmodule // top$pipeline$shade$1$lighting$u_h
module top$pipeline$shade$1$lighting$u_l(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= 'h0;
    end
endmodule // top$pipeline$shade$1$lighting$u_l
module top$pipeline$shade$1$lit_b(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$1$lit_b$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$lit_b$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$1$lit_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$1$lit_b$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_b
module top$pipeline$shade$1$lit_b$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_b$c_q
module top$pipeline$shade$1$lit_b$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lit_b$p
module top$pipeline$shade$1$lit_b$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_b$t
module top$pipeline$shade$1$lit_b$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_b$t_c
module top$pipeline$shade$1$lit_g(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$1$lit_g$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$lit_g$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$1$lit_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$1$lit_g$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_g
module top$pipeline$shade$1$lit_g$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_g$c_q
module top$pipeline$shade$1$lit_g$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lit_g$p
module top$pipeline$shade$1$lit_g$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_g$t
module top$pipeline$shade$1$lit_g$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_g$t_c
module top$pipeline$shade$1$lit_r(clock,a,b,c,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    input wire  [15:0] c;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 48'h80;
    localparam  shift = 8'h8;
    localparam  shift2 = 8'h10;
    localparam  max = 16'hff;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [15:0] c_q$d;
    wire  [15:0] c_q$q;
    reg  c_q$clock;
    reg  [47:0] t$d;
    wire  [47:0] t$q;
    reg  t$clock;
    reg  [47:0] t_c$d;
    wire  [47:0] t_c$q;
    reg  t_c$clock;
    
    // Local signals
    reg  [47:0] u;
    
    // Sub module instances
    top$pipeline$shade$1$lit_r$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$lit_r$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$pipeline$shade$1$lit_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    top$pipeline$shade$1$lit_r$t_c t_c(
        .d(t_c$d),
        .q(t_c$q),
        .clock(t_c$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        c_q$clock = clock;
        t$clock = clock;
        t_c$clock = clock;
        c_q$d = c_q$q;
        t$d = t$q;
        t_c$d = t_c$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        c_q$d = c;
        t$d = 48'(p$p) + half;
        t_c$d = 48'(p$p) + ((48'(c_q$q) << shift) | half);
        u = t_c$q + (t$q >> shift);
        y_pass = 16'(u >> shift);
        if ((u >> shift2) != 'h0) begin
            y_pass = max;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_r
module top$pipeline$shade$1$lit_r$c_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_r$c_q
module top$pipeline$shade$1$lit_r$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$lit_r$p
module top$pipeline$shade$1$lit_r$t(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_r$t
module top$pipeline$shade$1$lit_r$t_c(d,q,clock);
    
    // Module arguments
    input wire  [47:0] d;
    output reg  [47:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 48'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lit_r$t_c
module top$pipeline$shade$1$lut(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Constant declarations
    localparam  base = 24'h10000;
    localparam  window = 24'h11000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lut$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 64'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lut
module top$pipeline$shade$1$lut$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[255:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[7:0]][31:24], 8'd0, mem[read_address[7:0]][23:16], 8'd0, mem[read_address[7:0]][15:8], 8'd0, mem[read_address[7:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lut$ram
module top$pipeline$shade$1$lut_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$0
module top$pipeline$shade$1$lut_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$1
module top$pipeline$shade$1$lut_q$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$2
module top$pipeline$shade$1$lut_q$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$3
module top$pipeline$shade$1$lut_q$4(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$4
module top$pipeline$shade$1$lut_q$5(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$5
module top$pipeline$shade$1$lut_q$6(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$6
module top$pipeline$shade$1$lut_q$7(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$7
module top$pipeline$shade$1$lut_q$8(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lut_q$8
module top$pipeline$shade$1$mag_in$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mag_in$0
module top$pipeline$shade$1$mag_in$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mag_in$1
module top$pipeline$shade$1$mag_in$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mag_in$2
module top$pipeline$shade$1$mul_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_b$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$mul_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_b
module top$pipeline$shade$1$mul_b$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$mul_b$p
module top$pipeline$shade$1$mul_b$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mul_b$t
module top$pipeline$shade$1$mul_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_g$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$mul_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_g
module top$pipeline$shade$1$mul_g$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$mul_g$p
module top$pipeline$shade$1$mul_g$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mul_g$t
module top$pipeline$shade$1$mul_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_r$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$pipeline$shade$1$mul_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_r
module top$pipeline$shade$1$mul_r$p(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$shade$1$mul_r$p
module top$pipeline$shade$1$mul_r$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$mul_r$t
module top$pipeline$shade$1$neg_in$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$neg_in$0
module top$pipeline$shade$1$neg_in$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$neg_in$1
module top$pipeline$shade$1$neg_in$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$neg_in$2
module top$pipeline$shade$1$normal(clock,neg$0,neg$1,neg$2,mag$0,mag$1,mag$2,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2);
    
    // Module arguments
    input wire  clock;
    input wire  neg$0;
    input wire  neg$1;
    input wire  neg$2;
    input wire  [31:0] mag$0;
    input wire  [31:0] mag$1;
    input wire  [31:0] mag$2;
    output reg  q_neg$0;
    output reg  q_neg$1;
    output reg  q_neg$2;
    output reg  [6:0] q_mag$0;
    output reg  [6:0] q_mag$1;
    output reg  [6:0] q_mag$2;
    
    // Constant declarations
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  one = 8'h1;
    localparam  mag_bits = 8'h4;
    localparam  limit = 'hf;
    localparam  mask = 7'b1111;
    
    // Stub signals
    reg  [7:0] s_q$d;
    wire  [7:0] s_q$q;
    reg  s_q$clock;
    reg  neg_q$0$d;
    wire  neg_q$0$q;
    reg  neg_q$0$clock;
    reg  neg_q$1$d;
    wire  neg_q$1$q;
    reg  neg_q$1$clock;
    reg  neg_q$2$d;
    wire  neg_q$2$q;
    reg  neg_q$2$clock;
    reg  [31:0] mag_q$0$d;
    wire  [31:0] mag_q$0$q;
    reg  mag_q$0$clock;
    reg  [31:0] mag_q$1$d;
    wire  [31:0] mag_q$1$q;
    reg  mag_q$1$clock;
    reg  [31:0] mag_q$2$d;
    wire  [31:0] mag_q$2$q;
    reg  mag_q$2$clock;
    reg  [31:0] smear_q$d;
    wire  [31:0] smear_q$q;
    reg  smear_q$clock;
    reg  [31:0] half_q$d;
    wire  [31:0] half_q$q;
    reg  half_q$clock;
    reg  [31:0] half_m1_q$d;
    wire  [31:0] half_m1_q$q;
    reg  half_m1_q$clock;
    reg  [7:0] s_q2$d;
    wire  [7:0] s_q2$q;
    reg  s_q2$clock;
    reg  neg_q2$0$d;
    wire  neg_q2$0$q;
    reg  neg_q2$0$clock;
    reg  neg_q2$1$d;
    wire  neg_q2$1$q;
    reg  neg_q2$1$clock;
    reg  neg_q2$2$d;
    wire  neg_q2$2$q;
    reg  neg_q2$2$clock;
    reg  [31:0] sum_q$0$d;
    wire  [31:0] sum_q$0$q;
    reg  sum_q$0$clock;
    reg  [31:0] sum_q$1$d;
    wire  [31:0] sum_q$1$q;
    reg  sum_q$1$clock;
    reg  [31:0] sum_q$2$d;
    wire  [31:0] sum_q$2$q;
    reg  sum_q$2$clock;
    reg  [31:0] nz_mask_q$d;
    wire  [31:0] nz_mask_q$q;
    reg  nz_mask_q$clock;
    reg  [31:0] sat_mask_q$d;
    wire  [31:0] sat_mask_q$q;
    reg  sat_mask_q$clock;
    reg  out_neg$0$d;
    wire  out_neg$0$q;
    reg  out_neg$0$clock;
    reg  out_neg$1$d;
    wire  out_neg$1$q;
    reg  out_neg$1$clock;
    reg  out_neg$2$d;
    wire  out_neg$2$q;
    reg  out_neg$2$clock;
    reg  [6:0] out_mag$0$d;
    wire  [6:0] out_mag$0$q;
    reg  out_mag$0$clock;
    reg  [6:0] out_mag$1$d;
    wire  [6:0] out_mag$1$q;
    reg  out_mag$1$clock;
    reg  [6:0] out_mag$2$d;
    wire  [6:0] out_mag$2$q;
    reg  out_mag$2$clock;
    
    // Local signals
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [31:0] smear;
    reg  [6:0] q$0;
    reg  [6:0] q$1;
    reg  [6:0] q$2;
    
    // Sub module instances
    top$pipeline$shade$1$normal$s_q s_q(
        .d(s_q$d),
        .q(s_q$q),
        .clock(s_q$clock)
    );
    top$pipeline$shade$1$normal$neg_q$0 neg_q$0(
        .d(neg_q$0$d),
        .q(neg_q$0$q),
        .clock(neg_q$0$clock)
    );
    top$pipeline$shade$1$normal$neg_q$1 neg_q$1(
        .d(neg_q$1$d),
        .q(neg_q$1$q),
        .clock(neg_q$1$clock)
    );
    top$pipeline$shade$1$normal$neg_q$2 neg_q$2(
        .d(neg_q$2$d),
        .q(neg_q$2$q),
        .clock(neg_q$2$clock)
    );
    top$pipeline$shade$1$normal$mag_q$0 mag_q$0(
        .d(mag_q$0$d),
        .q(mag_q$0$q),
        .clock(mag_q$0$clock)
    );
    top$pipeline$shade$1$normal$mag_q$1 mag_q$1(
        .d(mag_q$1$d),
        .q(mag_q$1$q),
        .clock(mag_q$1$clock)
    );
    top$pipeline$shade$1$normal$mag_q$2 mag_q$2(
        .d(mag_q$2$d),
        .q(mag_q$2$q),
        .clock(mag_q$2$clock)
    );
    top$pipeline$shade$1$normal$smear_q smear_q(
        .d(smear_q$d),
        .q(smear_q$q),
        .clock(smear_q$clock)
    );
    top$pipeline$shade$1$normal$half_q half_q(
        .d(half_q$d),
        .q(half_q$q),
        .clock(half_q$clock)
    );
    top$pipeline$shade$1$normal$half_m1_q half_m1_q(
        .d(half_m1_q$d),
        .q(half_m1_q$q),
        .clock(half_m1_q$clock)
    );
    top$pipeline$shade$1$normal$s_q2 s_q2(
        .d(s_q2$d),
        .q(s_q2$q),
        .clock(s_q2$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$0 neg_q2$0(
        .d(neg_q2$0$d),
        .q(neg_q2$0$q),
        .clock(neg_q2$0$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$1 neg_q2$1(
        .d(neg_q2$1$d),
        .q(neg_q2$1$q),
        .clock(neg_q2$1$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$2 neg_q2$2(
        .d(neg_q2$2$d),
        .q(neg_q2$2$q),
        .clock(neg_q2$2$clock)
    );
    top$pipeline$shade$1$normal$sum_q$0 sum_q$0(
        .d(sum_q$0$d),
        .q(sum_q$0$q),
        .clock(sum_q$0$clock)
    );
    top$pipeline$shade$1$normal$sum_q$1 sum_q$1(
        .d(sum_q$1$d),
        .q(sum_q$1$q),
        .clock(sum_q$1$clock)
    );
    top$pipeline$shade$1$normal$sum_q$2 sum_q$2(
        .d(sum_q$2$d),
        .q(sum_q$2$q),
        .clock(sum_q$2$clock)
    );
    top$pipeline$shade$1$normal$nz_mask_q nz_mask_q(
        .d(nz_mask_q$d),
        .q(nz_mask_q$q),
        .clock(nz_mask_q$clock)
    );
    top$pipeline$shade$1$normal$sat_mask_q sat_mask_q(
        .d(sat_mask_q$d),
        .q(sat_mask_q$q),
        .clock(sat_mask_q$clock)
    );
    top$pipeline$shade$1$normal$out_neg$0 out_neg$0(
        .d(out_neg$0$d),
        .q(out_neg$0$q),
        .clock(out_neg$0$clock)
    );
    top$pipeline$shade$1$normal$out_neg$1 out_neg$1(
        .d(out_neg$1$d),
        .q(out_neg$1$q),
        .clock(out_neg$1$clock)
    );
    top$pipeline$shade$1$normal$out_neg$2 out_neg$2(
        .d(out_neg$2$d),
        .q(out_neg$2$q),
        .clock(out_neg$2$clock)
    );
    top$pipeline$shade$1$normal$out_mag$0 out_mag$0(
        .d(out_mag$0$d),
        .q(out_mag$0$q),
        .clock(out_mag$0$clock)
    );
    top$pipeline$shade$1$normal$out_mag$1 out_mag$1(
        .d(out_mag$1$d),
        .q(out_mag$1$q),
        .clock(out_mag$1$clock)
    );
    top$pipeline$shade$1$normal$out_mag$2 out_mag$2(
        .d(out_mag$2$d),
        .q(out_mag$2$q),
        .clock(out_mag$2$clock)
    );
    
    // Update code
    always @(*) begin
        s_q$clock = clock;
        s_q2$clock = clock;
        nz_mask_q$clock = clock;
        sat_mask_q$clock = clock;
        smear_q$clock = clock;
        half_q$clock = clock;
        half_m1_q$clock = clock;
        s_q$d = s_q$q;
        s_q2$d = s_q2$q;
        nz_mask_q$d = nz_mask_q$q;
        sat_mask_q$d = sat_mask_q$q;
        smear_q$d = smear_q$q;
        half_q$d = half_q$q;
        half_m1_q$d = half_m1_q$q;
        m = mag$0 | mag$1 | mag$2;
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s_q$d = 'h0;
        if (bl > mag_bits) begin
            s_q$d = bl - mag_bits;
        end
        smear = m | (m >> 'h1);
        smear = smear | (smear >> 'h2);
        smear = smear | (smear >> 'h4);
        smear = smear | (smear >> 'h8);
        smear = smear | (smear >> 'h10);
        smear_q$d = smear;
        half_q$d = (smear ^ (smear >> one)) >> mag_bits;
        half_m1_q$d = smear >> (mag_bits + one);
        s_q2$d = s_q$q;
        nz_mask_q$d = ~(smear_q$q >> mag_bits);
        sat_mask_q$d = ~(smear_q$q | limit);
        q$0 = 7'(sum_q$0$q >> s_q2$q);
        q$1 = 7'(sum_q$1$q >> s_q2$q);
        q$2 = 7'(sum_q$2$q >> s_q2$q);
        neg_q$0$clock = clock;
        mag_q$0$clock = clock;
        neg_q2$0$clock = clock;
        sum_q$0$clock = clock;
        out_neg$0$clock = clock;
        out_mag$0$clock = clock;
        neg_q$0$d = neg$0;
        mag_q$0$d = mag$0;
        neg_q2$0$d = neg_q$0$q;
        sum_q$0$d = mag_q$0$q + half_q$q;
        if (neg_q$0$q) begin
            sum_q$0$d = mag_q$0$q + half_m1_q$q;
        end
        out_mag$0$d = q$0 & mask;
        if ((sum_q$0$q & sat_mask_q$q) != 'h0) begin
            out_mag$0$d = mask;
        end
        out_neg$0$d = neg_q2$0$q & ((sum_q$0$q & nz_mask_q$q) != 'h0);
        q_neg$0 = out_neg$0$q;
        q_mag$0 = out_mag$0$q;
        neg_q$1$clock = clock;
        mag_q$1$clock = clock;
        neg_q2$1$clock = clock;
        sum_q$1$clock = clock;
        out_neg$1$clock = clock;
        out_mag$1$clock = clock;
        neg_q$1$d = neg$1;
        mag_q$1$d = mag$1;
        neg_q2$1$d = neg_q$1$q;
        sum_q$1$d = mag_q$1$q + half_q$q;
        if (neg_q$1$q) begin
            sum_q$1$d = mag_q$1$q + half_m1_q$q;
        end
        out_mag$1$d = q$1 & mask;
        if ((sum_q$1$q & sat_mask_q$q) != 'h0) begin
            out_mag$1$d = mask;
        end
        out_neg$1$d = neg_q2$1$q & ((sum_q$1$q & nz_mask_q$q) != 'h0);
        q_neg$1 = out_neg$1$q;
        q_mag$1 = out_mag$1$q;
        neg_q$2$clock = clock;
        mag_q$2$clock = clock;
        neg_q2$2$clock = clock;
        sum_q$2$clock = clock;
        out_neg$2$clock = clock;
        out_mag$2$clock = clock;
        neg_q$2$d = neg$2;
        mag_q$2$d = mag$2;
        neg_q2$2$d = neg_q$2$q;
        sum_q$2$d = mag_q$2$q + half_q$q;
        if (neg_q$2$q) begin
            sum_q$2$d = mag_q$2$q + half_m1_q$q;
        end
        out_mag$2$d = q$2 & mask;
        if ((sum_q$2$q & sat_mask_q$q) != 'h0) begin
            out_mag$2$d = mask;
        end
        out_neg$2$d = neg_q2$2$q & ((sum_q$2$q & nz_mask_q$q) != 'h0);
        q_neg$2 = out_neg$2$q;
        q_mag$2 = out_mag$2$q;
    end
    
endmodule // top$pipeline$shade$1$normal
module top$pipeline$shade$1$normal$half_m1_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$half_m1_q
module top$pipeline$shade$1$normal$half_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$half_q
module top$pipeline$shade$1$normal$mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$mag_q$0
module top$pipeline$shade$1$normal$mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$mag_q$1
module top$pipeline$shade$1$normal$mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$mag_q$2
module top$pipeline$shade$1$normal$neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q$0
module top$pipeline$shade$1$normal$neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q$1
module top$pipeline$shade$1$normal$neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q$2
module top$pipeline$shade$1$normal$neg_q2$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q2$0
module top$pipeline$shade$1$normal$neg_q2$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q2$1
module top$pipeline$shade$1$normal$neg_q2$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$neg_q2$2
module top$pipeline$shade$1$normal$nz_mask_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$nz_mask_q
module top$pipeline$shade$1$normal$out_mag$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$0
module top$pipeline$shade$1$normal$out_mag$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$1
module top$pipeline$shade$1$normal$out_mag$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$2
module top$pipeline$shade$1$normal$out_neg$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_neg$0
module top$pipeline$shade$1$normal$out_neg$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_neg$1
module top$pipeline$shade$1$normal$out_neg$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_neg$2
module top$pipeline$shade$1$normal$s_q(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$s_q
module top$pipeline$shade$1$normal$s_q2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$s_q2
module top$pipeline$shade$1$normal$sat_mask_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$sat_mask_q
module top$pipeline$shade$1$normal$smear_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$smear_q
module top$pipeline$shade$1$normal$sum_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$sum_q$0
module top$pipeline$shade$1$normal$sum_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$sum_q$1
module top$pipeline$shade$1$normal$sum_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$sum_q$2
module top$pipeline$shade$1$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$r_q
module top$pipeline$shade$1$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$0
module top$pipeline$shade$1$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$1
module top$pipeline$shade$1$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$2
module top$pipeline$shade$1$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$3
module top$pipeline$shade$1$shaded_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$shaded_q$0
module top$pipeline$shade$1$shaded_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$shaded_q$1
module top$pipeline$shade$1$shaded_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$shaded_q$2
module top$pipeline$shade$1$valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$0
module top$pipeline$shade$1$valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$1
module top$pipeline$shade$1$valid_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$10
module top$pipeline$shade$1$valid_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$11
module top$pipeline$shade$1$valid_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$12
module top$pipeline$shade$1$valid_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$13
module top$pipeline$shade$1$valid_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$14
module top$pipeline$shade$1$valid_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$15
module top$pipeline$shade$1$valid_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$16
module top$pipeline$shade$1$valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$2
module top$pipeline$shade$1$valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$3
module top$pipeline$shade$1$valid_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$4
module top$pipeline$shade$1$valid_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$5
module top$pipeline$shade$1$valid_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$6
module top$pipeline$shade$1$valid_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$7
module top$pipeline$shade$1$valid_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$8
module top$pipeline$shade$1$valid_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$valid_q$9
module top$pipeline$shade$1$value_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$0
module top$pipeline$shade$1$value_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$1
module top$pipeline$shade$1$value_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$10
module top$pipeline$shade$1$value_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$11
module top$pipeline$shade$1$value_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$12
module top$pipeline$shade$1$value_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$13
module top$pipeline$shade$1$value_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$14
module top$pipeline$shade$1$value_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$15
module top$pipeline$shade$1$value_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$2
module top$pipeline$shade$1$value_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$3
module top$pipeline$shade$1$value_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$4
module top$pipeline$shade$1$value_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$5
module top$pipeline$shade$1$value_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$6
module top$pipeline$shade$1$value_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$7
module top$pipeline$shade$1$value_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$8
module top$pipeline$shade$1$value_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$value_q$9
