module top$lanes$0$feed$abc(clock,beats,value,x,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_value,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] from_left_xm;
    input wire  [15:0] from_left_ym;
    input wire  [15:0] from_left_zm;
    input wire  [15:0] from_right_xp;
    input wire  [15:0] from_right_yp;
    input wire  [15:0] from_right_zp;
    output reg  [15:0] to_right_xm;
    output reg  [15:0] to_right_ym;
    output reg  [15:0] to_right_zm;
    output reg  [15:0] to_left_xp;
    output reg  [15:0] to_left_yp;
    output reg  [15:0] to_left_zp;
    output reg  [15:0] o_value;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  line_a$clock;
    reg  [15:0] line_a$data_in;
    reg  line_a$write_enable;
    wire  [15:0] line_a$data_out;
    reg  [15:0] line_a$last;
    reg  [15:0] reg_yp$d;
    wire  [15:0] reg_yp$q;
    reg  reg_yp$clock;
    reg  line_b$clock;
    reg  [15:0] line_b$data_in;
    reg  line_b$write_enable;
    wire  [15:0] line_b$data_out;
    reg  [15:0] line_b$last;
    reg  [15:0] reg_xm$d;
    wire  [15:0] reg_xm$q;
    reg  reg_xm$clock;
    reg  [15:0] reg_c$d;
    wire  [15:0] reg_c$q;
    reg  reg_c$clock;
    reg  line_c$clock;
    reg  [15:0] line_c$data_in;
    reg  line_c$write_enable;
    wire  [15:0] line_c$data_out;
    reg  [15:0] line_c$last;
    reg  line_d$clock;
    reg  [15:0] line_d$data_in;
    reg  line_d$write_enable;
    wire  [15:0] line_d$data_out;
    reg  [15:0] line_d$last;
    reg  [15:0] hop_xm$d;
    wire  [15:0] hop_xm$q;
    reg  hop_xm$clock;
    reg  [15:0] hop_ym$d;
    wire  [15:0] hop_ym$q;
    reg  hop_ym$clock;
    reg  [15:0] hop_zm$d;
    wire  [15:0] hop_zm$q;
    reg  hop_zm$clock;
    reg  [15:0] hop_xp$d;
    wire  [15:0] hop_xp$q;
    reg  hop_xp$clock;
    reg  [15:0] hop_yp$d;
    wire  [15:0] hop_yp$q;
    reg  hop_yp$clock;
    reg  [15:0] hop_zp$d;
    wire  [15:0] hop_zp$q;
    reg  hop_zp$clock;
    reg  [15:0] prev_xm$d;
    wire  [15:0] prev_xm$q;
    reg  prev_xm$clock;
    reg  [15:0] prev_xp$d;
    wire  [15:0] prev_xp$q;
    reg  prev_xp$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] last_a$d;
    wire  [15:0] last_a$q;
    reg  last_a$clock;
    reg  [15:0] last_b$d;
    wire  [15:0] last_b$q;
    reg  last_b$clock;
    reg  [15:0] last_d$d;
    wire  [15:0] last_d$q;
    reg  last_d$clock;
    
    // Local signals
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$0$feed$abc$line_a line_a(
        .clock(line_a$clock),
        .data_in(line_a$data_in),
        .write_enable(line_a$write_enable),
        .data_out(line_a$data_out),
        .last(line_a$last)
    );
    top$lanes$0$feed$abc$reg_yp reg_yp(
        .d(reg_yp$d),
        .q(reg_yp$q),
        .clock(reg_yp$clock)
    );
    top$lanes$0$feed$abc$line_b line_b(
        .clock(line_b$clock),
        .data_in(line_b$data_in),
        .write_enable(line_b$write_enable),
        .data_out(line_b$data_out),
        .last(line_b$last)
    );
    top$lanes$0$feed$abc$reg_xm reg_xm(
        .d(reg_xm$d),
        .q(reg_xm$q),
        .clock(reg_xm$clock)
    );
    top$lanes$0$feed$abc$reg_c reg_c(
        .d(reg_c$d),
        .q(reg_c$q),
        .clock(reg_c$clock)
    );
    top$lanes$0$feed$abc$line_c line_c(
        .clock(line_c$clock),
        .data_in(line_c$data_in),
        .write_enable(line_c$write_enable),
        .data_out(line_c$data_out),
        .last(line_c$last)
    );
    top$lanes$0$feed$abc$line_d line_d(
        .clock(line_d$clock),
        .data_in(line_d$data_in),
        .write_enable(line_d$write_enable),
        .data_out(line_d$data_out),
        .last(line_d$last)
    );
    top$lanes$0$feed$abc$hop_xm hop_xm(
        .d(hop_xm$d),
        .q(hop_xm$q),
        .clock(hop_xm$clock)
    );
    top$lanes$0$feed$abc$hop_ym hop_ym(
        .d(hop_ym$d),
        .q(hop_ym$q),
        .clock(hop_ym$clock)
    );
    top$lanes$0$feed$abc$hop_zm hop_zm(
        .d(hop_zm$d),
        .q(hop_zm$q),
        .clock(hop_zm$clock)
    );
    top$lanes$0$feed$abc$hop_xp hop_xp(
        .d(hop_xp$d),
        .q(hop_xp$q),
        .clock(hop_xp$clock)
    );
    top$lanes$0$feed$abc$hop_yp hop_yp(
        .d(hop_yp$d),
        .q(hop_yp$q),
        .clock(hop_yp$clock)
    );
    top$lanes$0$feed$abc$hop_zp hop_zp(
        .d(hop_zp$d),
        .q(hop_zp$q),
        .clock(hop_zp$clock)
    );
    top$lanes$0$feed$abc$prev_xm prev_xm(
        .d(prev_xm$d),
        .q(prev_xm$q),
        .clock(prev_xm$clock)
    );
    top$lanes$0$feed$abc$prev_xp prev_xp(
        .d(prev_xp$d),
        .q(prev_xp$q),
        .clock(prev_xp$clock)
    );
    top$lanes$0$feed$abc$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$0$feed$abc$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$0$feed$abc$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$0$feed$abc$last_a last_a(
        .d(last_a$d),
        .q(last_a$q),
        .clock(last_a$clock)
    );
    top$lanes$0$feed$abc$last_b last_b(
        .d(last_b$d),
        .q(last_b$q),
        .clock(last_b$clock)
    );
    top$lanes$0$feed$abc$last_d last_d(
        .d(last_d$d),
        .q(last_d$q),
        .clock(last_d$clock)
    );
    
    // Update code
    reg  [15:0] to_right_xm_pass;
    reg  [15:0] to_right_ym_pass;
    reg  [15:0] to_right_zm_pass;
    reg  [15:0] to_left_xp_pass;
    reg  [15:0] to_left_yp_pass;
    reg  [15:0] to_left_zp_pass;
    reg  [15:0] o_value_pass;
    reg  gx_neg_pass;
    reg  [15:0] gx_mag_pass;
    reg  gy_neg_pass;
    reg  [15:0] gy_mag_pass;
    reg  gz_neg_pass;
    reg  [15:0] gz_mag_pass;
    always @(*) begin
        reg_yp$clock = clock;
        reg_xm$clock = clock;
        reg_c$clock = clock;
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        last_a$clock = clock;
        last_b$clock = clock;
        last_d$clock = clock;
        reg_yp$d = reg_yp$q;
        reg_xm$d = reg_xm$q;
        reg_c$d = reg_c$q;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        last_a$d = last_a$q;
        last_b$d = last_b$q;
        last_d$d = last_d$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        last_d$d = slice_less_beam$q - 'h1;
        last_a$d = slice_less_beam$q - 'h2;
        last_b$d = beam$q - 'h1;
        line_a$last = last_a$q;
        line_b$last = last_b$q;
        line_c$last = last_b$q;
        line_d$last = last_d$q;
        line_a$clock = clock;
        line_b$clock = clock;
        line_c$clock = clock;
        line_d$clock = clock;
        line_a$data_in = value;
        line_a$write_enable = 1'b1;
        reg_yp$d = line_a$data_out;
        line_b$data_in = line_a$data_out;
        line_b$write_enable = 1'b1;
        reg_xm$d = line_b$data_out;
        reg_c$d = reg_xm$q;
        line_c$data_in = reg_xm$q;
        line_c$write_enable = 1'b1;
        line_d$data_in = line_c$data_out;
        line_d$write_enable = 1'b1;
        to_left_yp_pass = reg_yp$q;
        to_left_xp_pass = line_b$data_out;
        to_right_xm_pass = reg_xm$q;
        to_right_ym_pass = line_c$data_out;
        to_right_zm_pass = line_d$data_out;
        to_left_zp_pass = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((x & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((x & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg_pass = xp < xm;
        gx_mag_pass = xp - xm;
        if (xp < xm) begin
            gx_mag_pass = xm - xp;
        end
        gy_neg_pass = hop_yp$q < hop_ym$q;
        gy_mag_pass = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag_pass = hop_ym$q - hop_yp$q;
        end
        gz_neg_pass = hop_zp$q < hop_zm$q;
        gz_mag_pass = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag_pass = hop_zm$q - hop_zp$q;
        end
        o_value_pass = reg_c$q;
        if (~enabled) begin
            to_right_xm_pass = 'h0;
            to_right_ym_pass = 'h0;
            to_right_zm_pass = 'h0;
            to_left_xp_pass = 'h0;
            to_left_yp_pass = 'h0;
            to_left_zp_pass = 'h0;
            o_value_pass = 'h0;
            gx_mag_pass = 'h0;
            gy_mag_pass = 'h0;
            gz_mag_pass = 'h0;
            gx_neg_pass = 1'b0;
            gy_neg_pass = 1'b0;
            gz_neg_pass = 1'b0;
        end
        to_right_xm = to_right_xm_pass;
        to_right_ym = to_right_ym_pass;
        to_right_zm = to_right_zm_pass;
        to_left_xp = to_left_xp_pass;
        to_left_yp = to_left_yp_pass;
        to_left_zp = to_left_zp_pass;
        o_value = o_value_pass;
        gx_neg = gx_neg_pass;
        gx_mag = gx_mag_pass;
        gy_neg = gy_neg_pass;
        gy_mag = gy_mag_pass;
        gz_neg = gz_neg_pass;
        gz_mag = gz_mag_pass;
    end
    
endmodule // top$lanes$0$feed$abc
module top$lanes$0$feed$abc$beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$beam
module top$lanes$0$feed$abc$hop_xm(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_xm
module top$lanes$0$feed$abc$hop_xp(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_xp
module top$lanes$0$feed$abc$hop_ym(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_ym
module top$lanes$0$feed$abc$hop_yp(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_yp
module top$lanes$0$feed$abc$hop_zm(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_zm
module top$lanes$0$feed$abc$hop_zp(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$hop_zp
module top$lanes$0$feed$abc$last_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$last_a
module top$lanes$0$feed$abc$last_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$last_b
module top$lanes$0$feed$abc$last_d(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$last_d
module top$lanes$0$feed$abc$line_a(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbc;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$feed$abc$line_a$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$feed$abc$line_a$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$feed$abc$line_a$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$feed$abc$line_a$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$feed$abc$line_a$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$feed$abc$line_a$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$feed$abc$line_a$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$feed$abc$line_a$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$feed$abc$line_a$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$feed$abc$line_a$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$feed$abc$line_a$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$feed$abc$line_a
module top$lanes$0$feed$abc$line_a$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_a$bound
module top$lanes$0$feed$abc$line_a$head(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$head
module top$lanes$0$feed$abc$line_a$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_a$is_one
module top$lanes$0$feed$abc$line_a$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_a$is_short
module top$lanes$0$feed$abc$line_a$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_a$is_two
module top$lanes$0$feed$abc$line_a$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$one
module top$lanes$0$feed$abc$line_a$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$ptr
module top$lanes$0$feed$abc$line_a$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16316:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$feed$abc$line_a$ram
module top$lanes$0$feed$abc$line_a$rd(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$rd
module top$lanes$0$feed$abc$line_a$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$short
module top$lanes$0$feed$abc$line_a$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_a$two
module top$lanes$0$feed$abc$line_b(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$feed$abc$line_b$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$feed$abc$line_b$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$feed$abc$line_b$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$feed$abc$line_b$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$feed$abc$line_b$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$feed$abc$line_b$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$feed$abc$line_b$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$feed$abc$line_b$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$feed$abc$line_b$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$feed$abc$line_b$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$feed$abc$line_b$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$feed$abc$line_b
module top$lanes$0$feed$abc$line_b$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_b$bound
module top$lanes$0$feed$abc$line_b$head(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$head
module top$lanes$0$feed$abc$line_b$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_b$is_one
module top$lanes$0$feed$abc$line_b$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_b$is_short
module top$lanes$0$feed$abc$line_b$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_b$is_two
module top$lanes$0$feed$abc$line_b$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$one
module top$lanes$0$feed$abc$line_b$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$ptr
module top$lanes$0$feed$abc$line_b$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$feed$abc$line_b$ram
module top$lanes$0$feed$abc$line_b$rd(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$rd
module top$lanes$0$feed$abc$line_b$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$short
module top$lanes$0$feed$abc$line_b$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_b$two
module top$lanes$0$feed$abc$line_c(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$feed$abc$line_c$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$feed$abc$line_c$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$feed$abc$line_c$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$feed$abc$line_c$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$feed$abc$line_c$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$feed$abc$line_c$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$feed$abc$line_c$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$feed$abc$line_c$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$feed$abc$line_c$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$feed$abc$line_c$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$feed$abc$line_c$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$feed$abc$line_c
module top$lanes$0$feed$abc$line_c$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_c$bound
module top$lanes$0$feed$abc$line_c$head(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$head
module top$lanes$0$feed$abc$line_c$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_c$is_one
module top$lanes$0$feed$abc$line_c$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_c$is_short
module top$lanes$0$feed$abc$line_c$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_c$is_two
module top$lanes$0$feed$abc$line_c$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$one
module top$lanes$0$feed$abc$line_c$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$ptr
module top$lanes$0$feed$abc$line_c$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$feed$abc$line_c$ram
module top$lanes$0$feed$abc$line_c$rd(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$rd
module top$lanes$0$feed$abc$line_c$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$short
module top$lanes$0$feed$abc$line_c$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_c$two
module top$lanes$0$feed$abc$line_d(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbd;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$feed$abc$line_d$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$feed$abc$line_d$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$feed$abc$line_d$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$feed$abc$line_d$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$feed$abc$line_d$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$feed$abc$line_d$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$feed$abc$line_d$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$feed$abc$line_d$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$feed$abc$line_d$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$feed$abc$line_d$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$feed$abc$line_d$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$feed$abc$line_d
module top$lanes$0$feed$abc$line_d$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_d$bound
module top$lanes$0$feed$abc$line_d$head(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$head
module top$lanes$0$feed$abc$line_d$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_d$is_one
module top$lanes$0$feed$abc$line_d$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_d$is_short
module top$lanes$0$feed$abc$line_d$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$line_d$is_two
module top$lanes$0$feed$abc$line_d$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$one
module top$lanes$0$feed$abc$line_d$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$ptr
module top$lanes$0$feed$abc$line_d$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16317:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$feed$abc$line_d$ram
module top$lanes$0$feed$abc$line_d$rd(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$rd
module top$lanes$0$feed$abc$line_d$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$short
module top$lanes$0$feed$abc$line_d$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$line_d$two
module top$lanes$0$feed$abc$prev_xm(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$prev_xm
module top$lanes$0$feed$abc$prev_xp(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$prev_xp
module top$lanes$0$feed$abc$reg_c(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$reg_c
module top$lanes$0$feed$abc$reg_xm(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$reg_xm
module top$lanes$0$feed$abc$reg_yp(d,q,clock);
    
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
          
endmodule // top$lanes$0$feed$abc$reg_yp
module top$lanes$0$feed$abc$slice(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$slice
module top$lanes$0$feed$abc$slice_less_beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$feed$abc$slice_less_beam
module top$lanes$1$feed$abc(clock,beats,value,x,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_value,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] from_left_xm;
    input wire  [15:0] from_left_ym;
    input wire  [15:0] from_left_zm;
    input wire  [15:0] from_right_xp;
    input wire  [15:0] from_right_yp;
    input wire  [15:0] from_right_zp;
    output reg  [15:0] to_right_xm;
    output reg  [15:0] to_right_ym;
    output reg  [15:0] to_right_zm;
    output reg  [15:0] to_left_xp;
    output reg  [15:0] to_left_yp;
    output reg  [15:0] to_left_zp;
    output reg  [15:0] o_value;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  line_a$clock;
    reg  [15:0] line_a$data_in;
    reg  line_a$write_enable;
    wire  [15:0] line_a$data_out;
    reg  [15:0] line_a$last;
    reg  [15:0] reg_yp$d;
    wire  [15:0] reg_yp$q;
    reg  reg_yp$clock;
    reg  line_b$clock;
    reg  [15:0] line_b$data_in;
    reg  line_b$write_enable;
    wire  [15:0] line_b$data_out;
    reg  [15:0] line_b$last;
    reg  [15:0] reg_xm$d;
    wire  [15:0] reg_xm$q;
    reg  reg_xm$clock;
    reg  [15:0] reg_c$d;
    wire  [15:0] reg_c$q;
    reg  reg_c$clock;
    reg  line_c$clock;
    reg  [15:0] line_c$data_in;
    reg  line_c$write_enable;
    wire  [15:0] line_c$data_out;
    reg  [15:0] line_c$last;
    reg  line_d$clock;
    reg  [15:0] line_d$data_in;
    reg  line_d$write_enable;
    wire  [15:0] line_d$data_out;
    reg  [15:0] line_d$last;
    reg  [15:0] hop_xm$d;
    wire  [15:0] hop_xm$q;
    reg  hop_xm$clock;
    reg  [15:0] hop_ym$d;
    wire  [15:0] hop_ym$q;
    reg  hop_ym$clock;
    reg  [15:0] hop_zm$d;
    wire  [15:0] hop_zm$q;
    reg  hop_zm$clock;
    reg  [15:0] hop_xp$d;
    wire  [15:0] hop_xp$q;
    reg  hop_xp$clock;
    reg  [15:0] hop_yp$d;
    wire  [15:0] hop_yp$q;
    reg  hop_yp$clock;
    reg  [15:0] hop_zp$d;
    wire  [15:0] hop_zp$q;
    reg  hop_zp$clock;
    reg  [15:0] prev_xm$d;
    wire  [15:0] prev_xm$q;
    reg  prev_xm$clock;
    reg  [15:0] prev_xp$d;
    wire  [15:0] prev_xp$q;
    reg  prev_xp$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] last_a$d;
    wire  [15:0] last_a$q;
    reg  last_a$clock;
    reg  [15:0] last_b$d;
    wire  [15:0] last_b$q;
    reg  last_b$clock;
    reg  [15:0] last_d$d;
    wire  [15:0] last_d$q;
    reg  last_d$clock;
    
    // Local signals
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$1$feed$abc$line_a line_a(
        .clock(line_a$clock),
        .data_in(line_a$data_in),
        .write_enable(line_a$write_enable),
        .data_out(line_a$data_out),
        .last(line_a$last)
    );
    top$lanes$1$feed$abc$reg_yp reg_yp(
        .d(reg_yp$d),
        .q(reg_yp$q),
        .clock(reg_yp$clock)
    );
    top$lanes$1$feed$abc$line_b line_b(
        .clock(line_b$clock),
        .data_in(line_b$data_in),
        .write_enable(line_b$write_enable),
        .data_out(line_b$data_out),
        .last(line_b$last)
    );
    top$lanes$1$feed$abc$reg_xm reg_xm(
        .d(reg_xm$d),
        .q(reg_xm$q),
        .clock(reg_xm$clock)
    );
    top$lanes$1$feed$abc$reg_c reg_c(
        .d(reg_c$d),
        .q(reg_c$q),
        .clock(reg_c$clock)
    );
    top$lanes$1$feed$abc$line_c line_c(
        .clock(line_c$clock),
        .data_in(line_c$data_in),
        .write_enable(line_c$write_enable),
        .data_out(line_c$data_out),
        .last(line_c$last)
    );
    top$lanes$1$feed$abc$line_d line_d(
        .clock(line_d$clock),
        .data_in(line_d$data_in),
        .write_enable(line_d$write_enable),
        .data_out(line_d$data_out),
        .last(line_d$last)
    );
    top$lanes$1$feed$abc$hop_xm hop_xm(
        .d(hop_xm$d),
        .q(hop_xm$q),
        .clock(hop_xm$clock)
    );
    top$lanes$1$feed$abc$hop_ym hop_ym(
        .d(hop_ym$d),
        .q(hop_ym$q),
        .clock(hop_ym$clock)
    );
    top$lanes$1$feed$abc$hop_zm hop_zm(
        .d(hop_zm$d),
        .q(hop_zm$q),
        .clock(hop_zm$clock)
    );
    top$lanes$1$feed$abc$hop_xp hop_xp(
        .d(hop_xp$d),
        .q(hop_xp$q),
        .clock(hop_xp$clock)
    );
    top$lanes$1$feed$abc$hop_yp hop_yp(
        .d(hop_yp$d),
        .q(hop_yp$q),
        .clock(hop_yp$clock)
    );
    top$lanes$1$feed$abc$hop_zp hop_zp(
        .d(hop_zp$d),
        .q(hop_zp$q),
        .clock(hop_zp$clock)
    );
    top$lanes$1$feed$abc$prev_xm prev_xm(
        .d(prev_xm$d),
        .q(prev_xm$q),
        .clock(prev_xm$clock)
    );
    top$lanes$1$feed$abc$prev_xp prev_xp(
        .d(prev_xp$d),
        .q(prev_xp$q),
        .clock(prev_xp$clock)
    );
    top$lanes$1$feed$abc$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$1$feed$abc$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$1$feed$abc$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$1$feed$abc$last_a last_a(
        .d(last_a$d),
        .q(last_a$q),
        .clock(last_a$clock)
    );
    top$lanes$1$feed$abc$last_b last_b(
        .d(last_b$d),
        .q(last_b$q),
        .clock(last_b$clock)
    );
    top$lanes$1$feed$abc$last_d last_d(
        .d(last_d$d),
        .q(last_d$q),
        .clock(last_d$clock)
    );
    
    // Update code
    reg  [15:0] to_right_xm_pass;
    reg  [15:0] to_right_ym_pass;
    reg  [15:0] to_right_zm_pass;
    reg  [15:0] to_left_xp_pass;
    reg  [15:0] to_left_yp_pass;
    reg  [15:0] to_left_zp_pass;
    reg  [15:0] o_value_pass;
    reg  gx_neg_pass;
    reg  [15:0] gx_mag_pass;
    reg  gy_neg_pass;
    reg  [15:0] gy_mag_pass;
    reg  gz_neg_pass;
    reg  [15:0] gz_mag_pass;
    always @(*) begin
        reg_yp$clock = clock;
        reg_xm$clock = clock;
        reg_c$clock = clock;
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        last_a$clock = clock;
        last_b$clock = clock;
        last_d$clock = clock;
        reg_yp$d = reg_yp$q;
        reg_xm$d = reg_xm$q;
        reg_c$d = reg_c$q;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        last_a$d = last_a$q;
        last_b$d = last_b$q;
        last_d$d = last_d$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        last_d$d = slice_less_beam$q - 'h1;
        last_a$d = slice_less_beam$q - 'h2;
        last_b$d = beam$q - 'h1;
        line_a$last = last_a$q;
        line_b$last = last_b$q;
        line_c$last = last_b$q;
        line_d$last = last_d$q;
        line_a$clock = clock;
        line_b$clock = clock;
        line_c$clock = clock;
        line_d$clock = clock;
        line_a$data_in = value;
        line_a$write_enable = 1'b1;
        reg_yp$d = line_a$data_out;
        line_b$data_in = line_a$data_out;
        line_b$write_enable = 1'b1;
        reg_xm$d = line_b$data_out;
        reg_c$d = reg_xm$q;
        line_c$data_in = reg_xm$q;
        line_c$write_enable = 1'b1;
        line_d$data_in = line_c$data_out;
        line_d$write_enable = 1'b1;
        to_left_yp_pass = reg_yp$q;
        to_left_xp_pass = line_b$data_out;
        to_right_xm_pass = reg_xm$q;
        to_right_ym_pass = line_c$data_out;
        to_right_zm_pass = line_d$data_out;
        to_left_zp_pass = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((x & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((x & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg_pass = xp < xm;
        gx_mag_pass = xp - xm;
        if (xp < xm) begin
            gx_mag_pass = xm - xp;
        end
        gy_neg_pass = hop_yp$q < hop_ym$q;
        gy_mag_pass = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag_pass = hop_ym$q - hop_yp$q;
        end
        gz_neg_pass = hop_zp$q < hop_zm$q;
        gz_mag_pass = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag_pass = hop_zm$q - hop_zp$q;
        end
        o_value_pass = reg_c$q;
        if (~enabled) begin
            to_right_xm_pass = 'h0;
            to_right_ym_pass = 'h0;
            to_right_zm_pass = 'h0;
            to_left_xp_pass = 'h0;
            to_left_yp_pass = 'h0;
            to_left_zp_pass = 'h0;
            o_value_pass = 'h0;
            gx_mag_pass = 'h0;
            gy_mag_pass = 'h0;
            gz_mag_pass = 'h0;
            gx_neg_pass = 1'b0;
            gy_neg_pass = 1'b0;
            gz_neg_pass = 1'b0;
        end
        to_right_xm = to_right_xm_pass;
        to_right_ym = to_right_ym_pass;
        to_right_zm = to_right_zm_pass;
        to_left_xp = to_left_xp_pass;
        to_left_yp = to_left_yp_pass;
        to_left_zp = to_left_zp_pass;
        o_value = o_value_pass;
        gx_neg = gx_neg_pass;
        gx_mag = gx_mag_pass;
        gy_neg = gy_neg_pass;
        gy_mag = gy_mag_pass;
        gz_neg = gz_neg_pass;
        gz_mag = gz_mag_pass;
    end
    
endmodule // top$lanes$1$feed$abc
module top$lanes$1$feed$abc$beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$beam
module top$lanes$1$feed$abc$hop_xm(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_xm
module top$lanes$1$feed$abc$hop_xp(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_xp
module top$lanes$1$feed$abc$hop_ym(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_ym
module top$lanes$1$feed$abc$hop_yp(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_yp
module top$lanes$1$feed$abc$hop_zm(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_zm
module top$lanes$1$feed$abc$hop_zp(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$hop_zp
module top$lanes$1$feed$abc$last_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$last_a
module top$lanes$1$feed$abc$last_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$last_b
module top$lanes$1$feed$abc$last_d(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$last_d
module top$lanes$1$feed$abc$line_a(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbc;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$feed$abc$line_a$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$feed$abc$line_a$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$feed$abc$line_a$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$feed$abc$line_a$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$feed$abc$line_a$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$feed$abc$line_a$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$feed$abc$line_a$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$feed$abc$line_a$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$feed$abc$line_a$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$feed$abc$line_a$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$feed$abc$line_a$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$feed$abc$line_a
module top$lanes$1$feed$abc$line_a$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_a$bound
module top$lanes$1$feed$abc$line_a$head(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$head
module top$lanes$1$feed$abc$line_a$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_a$is_one
module top$lanes$1$feed$abc$line_a$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_a$is_short
module top$lanes$1$feed$abc$line_a$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_a$is_two
module top$lanes$1$feed$abc$line_a$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$one
module top$lanes$1$feed$abc$line_a$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$ptr
module top$lanes$1$feed$abc$line_a$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16316:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$feed$abc$line_a$ram
module top$lanes$1$feed$abc$line_a$rd(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$rd
module top$lanes$1$feed$abc$line_a$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$short
module top$lanes$1$feed$abc$line_a$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_a$two
module top$lanes$1$feed$abc$line_b(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$feed$abc$line_b$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$feed$abc$line_b$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$feed$abc$line_b$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$feed$abc$line_b$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$feed$abc$line_b$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$feed$abc$line_b$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$feed$abc$line_b$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$feed$abc$line_b$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$feed$abc$line_b$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$feed$abc$line_b$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$feed$abc$line_b$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$feed$abc$line_b
module top$lanes$1$feed$abc$line_b$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_b$bound
module top$lanes$1$feed$abc$line_b$head(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$head
module top$lanes$1$feed$abc$line_b$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_b$is_one
module top$lanes$1$feed$abc$line_b$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_b$is_short
module top$lanes$1$feed$abc$line_b$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_b$is_two
module top$lanes$1$feed$abc$line_b$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$one
module top$lanes$1$feed$abc$line_b$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$ptr
module top$lanes$1$feed$abc$line_b$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$feed$abc$line_b$ram
module top$lanes$1$feed$abc$line_b$rd(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$rd
module top$lanes$1$feed$abc$line_b$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$short
module top$lanes$1$feed$abc$line_b$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_b$two
module top$lanes$1$feed$abc$line_c(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$feed$abc$line_c$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$feed$abc$line_c$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$feed$abc$line_c$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$feed$abc$line_c$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$feed$abc$line_c$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$feed$abc$line_c$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$feed$abc$line_c$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$feed$abc$line_c$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$feed$abc$line_c$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$feed$abc$line_c$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$feed$abc$line_c$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$feed$abc$line_c
module top$lanes$1$feed$abc$line_c$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_c$bound
module top$lanes$1$feed$abc$line_c$head(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$head
module top$lanes$1$feed$abc$line_c$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_c$is_one
module top$lanes$1$feed$abc$line_c$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_c$is_short
module top$lanes$1$feed$abc$line_c$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_c$is_two
module top$lanes$1$feed$abc$line_c$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$one
module top$lanes$1$feed$abc$line_c$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$ptr
module top$lanes$1$feed$abc$line_c$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$feed$abc$line_c$ram
module top$lanes$1$feed$abc$line_c$rd(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$rd
module top$lanes$1$feed$abc$line_c$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$short
module top$lanes$1$feed$abc$line_c$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_c$two
module top$lanes$1$feed$abc$line_d(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbd;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$feed$abc$line_d$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$feed$abc$line_d$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$feed$abc$line_d$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$feed$abc$line_d$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$feed$abc$line_d$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$feed$abc$line_d$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$feed$abc$line_d$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$feed$abc$line_d$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$feed$abc$line_d$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$feed$abc$line_d$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$feed$abc$line_d$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$feed$abc$line_d
module top$lanes$1$feed$abc$line_d$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_d$bound
module top$lanes$1$feed$abc$line_d$head(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$head
module top$lanes$1$feed$abc$line_d$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_d$is_one
module top$lanes$1$feed$abc$line_d$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_d$is_short
module top$lanes$1$feed$abc$line_d$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$line_d$is_two
module top$lanes$1$feed$abc$line_d$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$one
module top$lanes$1$feed$abc$line_d$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$ptr
module top$lanes$1$feed$abc$line_d$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16317:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$feed$abc$line_d$ram
module top$lanes$1$feed$abc$line_d$rd(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$rd
module top$lanes$1$feed$abc$line_d$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$short
module top$lanes$1$feed$abc$line_d$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$line_d$two
module top$lanes$1$feed$abc$prev_xm(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$prev_xm
module top$lanes$1$feed$abc$prev_xp(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$prev_xp
module top$lanes$1$feed$abc$reg_c(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$reg_c
module top$lanes$1$feed$abc$reg_xm(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$reg_xm
module top$lanes$1$feed$abc$reg_yp(d,q,clock);
    
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
          
endmodule // top$lanes$1$feed$abc$reg_yp
module top$lanes$1$feed$abc$slice(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$slice
module top$lanes$1$feed$abc$slice_less_beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$feed$abc$slice_less_beam
module top$lanes$2$feed$abc(clock,beats,value,x,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_value,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] from_left_xm;
    input wire  [15:0] from_left_ym;
    input wire  [15:0] from_left_zm;
    input wire  [15:0] from_right_xp;
    input wire  [15:0] from_right_yp;
    input wire  [15:0] from_right_zp;
    output reg  [15:0] to_right_xm;
    output reg  [15:0] to_right_ym;
    output reg  [15:0] to_right_zm;
    output reg  [15:0] to_left_xp;
    output reg  [15:0] to_left_yp;
    output reg  [15:0] to_left_zp;
    output reg  [15:0] o_value;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  line_a$clock;
    reg  [15:0] line_a$data_in;
    reg  line_a$write_enable;
    wire  [15:0] line_a$data_out;
    reg  [15:0] line_a$last;
    reg  [15:0] reg_yp$d;
    wire  [15:0] reg_yp$q;
    reg  reg_yp$clock;
    reg  line_b$clock;
    reg  [15:0] line_b$data_in;
    reg  line_b$write_enable;
    wire  [15:0] line_b$data_out;
    reg  [15:0] line_b$last;
    reg  [15:0] reg_xm$d;
    wire  [15:0] reg_xm$q;
    reg  reg_xm$clock;
    reg  [15:0] reg_c$d;
    wire  [15:0] reg_c$q;
    reg  reg_c$clock;
    reg  line_c$clock;
    reg  [15:0] line_c$data_in;
    reg  line_c$write_enable;
    wire  [15:0] line_c$data_out;
    reg  [15:0] line_c$last;
    reg  line_d$clock;
    reg  [15:0] line_d$data_in;
    reg  line_d$write_enable;
    wire  [15:0] line_d$data_out;
    reg  [15:0] line_d$last;
    reg  [15:0] hop_xm$d;
    wire  [15:0] hop_xm$q;
    reg  hop_xm$clock;
    reg  [15:0] hop_ym$d;
    wire  [15:0] hop_ym$q;
    reg  hop_ym$clock;
    reg  [15:0] hop_zm$d;
    wire  [15:0] hop_zm$q;
    reg  hop_zm$clock;
    reg  [15:0] hop_xp$d;
    wire  [15:0] hop_xp$q;
    reg  hop_xp$clock;
    reg  [15:0] hop_yp$d;
    wire  [15:0] hop_yp$q;
    reg  hop_yp$clock;
    reg  [15:0] hop_zp$d;
    wire  [15:0] hop_zp$q;
    reg  hop_zp$clock;
    reg  [15:0] prev_xm$d;
    wire  [15:0] prev_xm$q;
    reg  prev_xm$clock;
    reg  [15:0] prev_xp$d;
    wire  [15:0] prev_xp$q;
    reg  prev_xp$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] last_a$d;
    wire  [15:0] last_a$q;
    reg  last_a$clock;
    reg  [15:0] last_b$d;
    wire  [15:0] last_b$q;
    reg  last_b$clock;
    reg  [15:0] last_d$d;
    wire  [15:0] last_d$q;
    reg  last_d$clock;
    
    // Local signals
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$2$feed$abc$line_a line_a(
        .clock(line_a$clock),
        .data_in(line_a$data_in),
        .write_enable(line_a$write_enable),
        .data_out(line_a$data_out),
        .last(line_a$last)
    );
    top$lanes$2$feed$abc$reg_yp reg_yp(
        .d(reg_yp$d),
        .q(reg_yp$q),
        .clock(reg_yp$clock)
    );
    top$lanes$2$feed$abc$line_b line_b(
        .clock(line_b$clock),
        .data_in(line_b$data_in),
        .write_enable(line_b$write_enable),
        .data_out(line_b$data_out),
        .last(line_b$last)
    );
    top$lanes$2$feed$abc$reg_xm reg_xm(
        .d(reg_xm$d),
        .q(reg_xm$q),
        .clock(reg_xm$clock)
    );
    top$lanes$2$feed$abc$reg_c reg_c(
        .d(reg_c$d),
        .q(reg_c$q),
        .clock(reg_c$clock)
    );
    top$lanes$2$feed$abc$line_c line_c(
        .clock(line_c$clock),
        .data_in(line_c$data_in),
        .write_enable(line_c$write_enable),
        .data_out(line_c$data_out),
        .last(line_c$last)
    );
    top$lanes$2$feed$abc$line_d line_d(
        .clock(line_d$clock),
        .data_in(line_d$data_in),
        .write_enable(line_d$write_enable),
        .data_out(line_d$data_out),
        .last(line_d$last)
    );
    top$lanes$2$feed$abc$hop_xm hop_xm(
        .d(hop_xm$d),
        .q(hop_xm$q),
        .clock(hop_xm$clock)
    );
    top$lanes$2$feed$abc$hop_ym hop_ym(
        .d(hop_ym$d),
        .q(hop_ym$q),
        .clock(hop_ym$clock)
    );
    top$lanes$2$feed$abc$hop_zm hop_zm(
        .d(hop_zm$d),
        .q(hop_zm$q),
        .clock(hop_zm$clock)
    );
    top$lanes$2$feed$abc$hop_xp hop_xp(
        .d(hop_xp$d),
        .q(hop_xp$q),
        .clock(hop_xp$clock)
    );
    top$lanes$2$feed$abc$hop_yp hop_yp(
        .d(hop_yp$d),
        .q(hop_yp$q),
        .clock(hop_yp$clock)
    );
    top$lanes$2$feed$abc$hop_zp hop_zp(
        .d(hop_zp$d),
        .q(hop_zp$q),
        .clock(hop_zp$clock)
    );
    top$lanes$2$feed$abc$prev_xm prev_xm(
        .d(prev_xm$d),
        .q(prev_xm$q),
        .clock(prev_xm$clock)
    );
    top$lanes$2$feed$abc$prev_xp prev_xp(
        .d(prev_xp$d),
        .q(prev_xp$q),
        .clock(prev_xp$clock)
    );
    top$lanes$2$feed$abc$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$2$feed$abc$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$2$feed$abc$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$2$feed$abc$last_a last_a(
        .d(last_a$d),
        .q(last_a$q),
        .clock(last_a$clock)
    );
    top$lanes$2$feed$abc$last_b last_b(
        .d(last_b$d),
        .q(last_b$q),
        .clock(last_b$clock)
    );
    top$lanes$2$feed$abc$last_d last_d(
        .d(last_d$d),
        .q(last_d$q),
        .clock(last_d$clock)
    );
    
    // Update code
    reg  [15:0] to_right_xm_pass;
    reg  [15:0] to_right_ym_pass;
    reg  [15:0] to_right_zm_pass;
    reg  [15:0] to_left_xp_pass;
    reg  [15:0] to_left_yp_pass;
    reg  [15:0] to_left_zp_pass;
    reg  [15:0] o_value_pass;
    reg  gx_neg_pass;
    reg  [15:0] gx_mag_pass;
    reg  gy_neg_pass;
    reg  [15:0] gy_mag_pass;
    reg  gz_neg_pass;
    reg  [15:0] gz_mag_pass;
    always @(*) begin
        reg_yp$clock = clock;
        reg_xm$clock = clock;
        reg_c$clock = clock;
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        last_a$clock = clock;
        last_b$clock = clock;
        last_d$clock = clock;
        reg_yp$d = reg_yp$q;
        reg_xm$d = reg_xm$q;
        reg_c$d = reg_c$q;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        last_a$d = last_a$q;
        last_b$d = last_b$q;
        last_d$d = last_d$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        last_d$d = slice_less_beam$q - 'h1;
        last_a$d = slice_less_beam$q - 'h2;
        last_b$d = beam$q - 'h1;
        line_a$last = last_a$q;
        line_b$last = last_b$q;
        line_c$last = last_b$q;
        line_d$last = last_d$q;
        line_a$clock = clock;
        line_b$clock = clock;
        line_c$clock = clock;
        line_d$clock = clock;
        line_a$data_in = value;
        line_a$write_enable = 1'b1;
        reg_yp$d = line_a$data_out;
        line_b$data_in = line_a$data_out;
        line_b$write_enable = 1'b1;
        reg_xm$d = line_b$data_out;
        reg_c$d = reg_xm$q;
        line_c$data_in = reg_xm$q;
        line_c$write_enable = 1'b1;
        line_d$data_in = line_c$data_out;
        line_d$write_enable = 1'b1;
        to_left_yp_pass = reg_yp$q;
        to_left_xp_pass = line_b$data_out;
        to_right_xm_pass = reg_xm$q;
        to_right_ym_pass = line_c$data_out;
        to_right_zm_pass = line_d$data_out;
        to_left_zp_pass = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((x & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((x & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg_pass = xp < xm;
        gx_mag_pass = xp - xm;
        if (xp < xm) begin
            gx_mag_pass = xm - xp;
        end
        gy_neg_pass = hop_yp$q < hop_ym$q;
        gy_mag_pass = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag_pass = hop_ym$q - hop_yp$q;
        end
        gz_neg_pass = hop_zp$q < hop_zm$q;
        gz_mag_pass = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag_pass = hop_zm$q - hop_zp$q;
        end
        o_value_pass = reg_c$q;
        if (~enabled) begin
            to_right_xm_pass = 'h0;
            to_right_ym_pass = 'h0;
            to_right_zm_pass = 'h0;
            to_left_xp_pass = 'h0;
            to_left_yp_pass = 'h0;
            to_left_zp_pass = 'h0;
            o_value_pass = 'h0;
            gx_mag_pass = 'h0;
            gy_mag_pass = 'h0;
            gz_mag_pass = 'h0;
            gx_neg_pass = 1'b0;
            gy_neg_pass = 1'b0;
            gz_neg_pass = 1'b0;
        end
        to_right_xm = to_right_xm_pass;
        to_right_ym = to_right_ym_pass;
        to_right_zm = to_right_zm_pass;
        to_left_xp = to_left_xp_pass;
        to_left_yp = to_left_yp_pass;
        to_left_zp = to_left_zp_pass;
        o_value = o_value_pass;
        gx_neg = gx_neg_pass;
        gx_mag = gx_mag_pass;
        gy_neg = gy_neg_pass;
        gy_mag = gy_mag_pass;
        gz_neg = gz_neg_pass;
        gz_mag = gz_mag_pass;
    end
    
endmodule // top$lanes$2$feed$abc
module top$lanes$2$feed$abc$beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$beam
module top$lanes$2$feed$abc$hop_xm(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_xm
module top$lanes$2$feed$abc$hop_xp(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_xp
module top$lanes$2$feed$abc$hop_ym(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_ym
module top$lanes$2$feed$abc$hop_yp(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_yp
module top$lanes$2$feed$abc$hop_zm(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_zm
module top$lanes$2$feed$abc$hop_zp(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$hop_zp
module top$lanes$2$feed$abc$last_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$last_a
module top$lanes$2$feed$abc$last_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$last_b
module top$lanes$2$feed$abc$last_d(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$last_d
module top$lanes$2$feed$abc$line_a(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbc;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$2$feed$abc$line_a$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$2$feed$abc$line_a$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$2$feed$abc$line_a$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$2$feed$abc$line_a$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$2$feed$abc$line_a$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$2$feed$abc$line_a$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$2$feed$abc$line_a$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$2$feed$abc$line_a$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$2$feed$abc$line_a$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$2$feed$abc$line_a$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$2$feed$abc$line_a$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$2$feed$abc$line_a
module top$lanes$2$feed$abc$line_a$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_a$bound
module top$lanes$2$feed$abc$line_a$head(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$head
module top$lanes$2$feed$abc$line_a$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_a$is_one
module top$lanes$2$feed$abc$line_a$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_a$is_short
module top$lanes$2$feed$abc$line_a$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_a$is_two
module top$lanes$2$feed$abc$line_a$one(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$one
module top$lanes$2$feed$abc$line_a$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$ptr
module top$lanes$2$feed$abc$line_a$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16316:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$2$feed$abc$line_a$ram
module top$lanes$2$feed$abc$line_a$rd(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$rd
module top$lanes$2$feed$abc$line_a$short(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$short
module top$lanes$2$feed$abc$line_a$two(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_a$two
module top$lanes$2$feed$abc$line_b(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$2$feed$abc$line_b$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$2$feed$abc$line_b$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$2$feed$abc$line_b$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$2$feed$abc$line_b$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$2$feed$abc$line_b$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$2$feed$abc$line_b$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$2$feed$abc$line_b$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$2$feed$abc$line_b$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$2$feed$abc$line_b$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$2$feed$abc$line_b$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$2$feed$abc$line_b$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$2$feed$abc$line_b
module top$lanes$2$feed$abc$line_b$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_b$bound
module top$lanes$2$feed$abc$line_b$head(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$head
module top$lanes$2$feed$abc$line_b$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_b$is_one
module top$lanes$2$feed$abc$line_b$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_b$is_short
module top$lanes$2$feed$abc$line_b$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_b$is_two
module top$lanes$2$feed$abc$line_b$one(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$one
module top$lanes$2$feed$abc$line_b$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$ptr
module top$lanes$2$feed$abc$line_b$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$2$feed$abc$line_b$ram
module top$lanes$2$feed$abc$line_b$rd(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$rd
module top$lanes$2$feed$abc$line_b$short(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$short
module top$lanes$2$feed$abc$line_b$two(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_b$two
module top$lanes$2$feed$abc$line_c(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$2$feed$abc$line_c$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$2$feed$abc$line_c$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$2$feed$abc$line_c$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$2$feed$abc$line_c$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$2$feed$abc$line_c$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$2$feed$abc$line_c$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$2$feed$abc$line_c$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$2$feed$abc$line_c$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$2$feed$abc$line_c$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$2$feed$abc$line_c$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$2$feed$abc$line_c$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$2$feed$abc$line_c
module top$lanes$2$feed$abc$line_c$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_c$bound
module top$lanes$2$feed$abc$line_c$head(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$head
module top$lanes$2$feed$abc$line_c$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_c$is_one
module top$lanes$2$feed$abc$line_c$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_c$is_short
module top$lanes$2$feed$abc$line_c$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_c$is_two
module top$lanes$2$feed$abc$line_c$one(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$one
module top$lanes$2$feed$abc$line_c$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$ptr
module top$lanes$2$feed$abc$line_c$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$2$feed$abc$line_c$ram
module top$lanes$2$feed$abc$line_c$rd(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$rd
module top$lanes$2$feed$abc$line_c$short(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$short
module top$lanes$2$feed$abc$line_c$two(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_c$two
module top$lanes$2$feed$abc$line_d(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbd;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$2$feed$abc$line_d$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$2$feed$abc$line_d$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$2$feed$abc$line_d$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$2$feed$abc$line_d$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$2$feed$abc$line_d$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$2$feed$abc$line_d$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$2$feed$abc$line_d$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$2$feed$abc$line_d$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$2$feed$abc$line_d$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$2$feed$abc$line_d$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$2$feed$abc$line_d$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$2$feed$abc$line_d
module top$lanes$2$feed$abc$line_d$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_d$bound
module top$lanes$2$feed$abc$line_d$head(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$head
module top$lanes$2$feed$abc$line_d$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_d$is_one
module top$lanes$2$feed$abc$line_d$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_d$is_short
module top$lanes$2$feed$abc$line_d$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$line_d$is_two
module top$lanes$2$feed$abc$line_d$one(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$one
module top$lanes$2$feed$abc$line_d$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$ptr
module top$lanes$2$feed$abc$line_d$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16317:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$2$feed$abc$line_d$ram
module top$lanes$2$feed$abc$line_d$rd(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$rd
module top$lanes$2$feed$abc$line_d$short(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$short
module top$lanes$2$feed$abc$line_d$two(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$line_d$two
module top$lanes$2$feed$abc$prev_xm(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$prev_xm
module top$lanes$2$feed$abc$prev_xp(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$prev_xp
module top$lanes$2$feed$abc$reg_c(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$reg_c
module top$lanes$2$feed$abc$reg_xm(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$reg_xm
module top$lanes$2$feed$abc$reg_yp(d,q,clock);
    
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
          
endmodule // top$lanes$2$feed$abc$reg_yp
module top$lanes$2$feed$abc$slice(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$slice
module top$lanes$2$feed$abc$slice_less_beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$feed$abc$slice_less_beam
module top$lanes$3$feed$abc(clock,beats,value,x,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_value,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] from_left_xm;
    input wire  [15:0] from_left_ym;
    input wire  [15:0] from_left_zm;
    input wire  [15:0] from_right_xp;
    input wire  [15:0] from_right_yp;
    input wire  [15:0] from_right_zp;
    output reg  [15:0] to_right_xm;
    output reg  [15:0] to_right_ym;
    output reg  [15:0] to_right_zm;
    output reg  [15:0] to_left_xp;
    output reg  [15:0] to_left_yp;
    output reg  [15:0] to_left_zp;
    output reg  [15:0] o_value;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  line_a$clock;
    reg  [15:0] line_a$data_in;
    reg  line_a$write_enable;
    wire  [15:0] line_a$data_out;
    reg  [15:0] line_a$last;
    reg  [15:0] reg_yp$d;
    wire  [15:0] reg_yp$q;
    reg  reg_yp$clock;
    reg  line_b$clock;
    reg  [15:0] line_b$data_in;
    reg  line_b$write_enable;
    wire  [15:0] line_b$data_out;
    reg  [15:0] line_b$last;
    reg  [15:0] reg_xm$d;
    wire  [15:0] reg_xm$q;
    reg  reg_xm$clock;
    reg  [15:0] reg_c$d;
    wire  [15:0] reg_c$q;
    reg  reg_c$clock;
    reg  line_c$clock;
    reg  [15:0] line_c$data_in;
    reg  line_c$write_enable;
    wire  [15:0] line_c$data_out;
    reg  [15:0] line_c$last;
    reg  line_d$clock;
    reg  [15:0] line_d$data_in;
    reg  line_d$write_enable;
    wire  [15:0] line_d$data_out;
    reg  [15:0] line_d$last;
    reg  [15:0] hop_xm$d;
    wire  [15:0] hop_xm$q;
    reg  hop_xm$clock;
    reg  [15:0] hop_ym$d;
    wire  [15:0] hop_ym$q;
    reg  hop_ym$clock;
    reg  [15:0] hop_zm$d;
    wire  [15:0] hop_zm$q;
    reg  hop_zm$clock;
    reg  [15:0] hop_xp$d;
    wire  [15:0] hop_xp$q;
    reg  hop_xp$clock;
    reg  [15:0] hop_yp$d;
    wire  [15:0] hop_yp$q;
    reg  hop_yp$clock;
    reg  [15:0] hop_zp$d;
    wire  [15:0] hop_zp$q;
    reg  hop_zp$clock;
    reg  [15:0] prev_xm$d;
    wire  [15:0] prev_xm$q;
    reg  prev_xm$clock;
    reg  [15:0] prev_xp$d;
    wire  [15:0] prev_xp$q;
    reg  prev_xp$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] last_a$d;
    wire  [15:0] last_a$q;
    reg  last_a$clock;
    reg  [15:0] last_b$d;
    wire  [15:0] last_b$q;
    reg  last_b$clock;
    reg  [15:0] last_d$d;
    wire  [15:0] last_d$q;
    reg  last_d$clock;
    
    // Local signals
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$3$feed$abc$line_a line_a(
        .clock(line_a$clock),
        .data_in(line_a$data_in),
        .write_enable(line_a$write_enable),
        .data_out(line_a$data_out),
        .last(line_a$last)
    );
    top$lanes$3$feed$abc$reg_yp reg_yp(
        .d(reg_yp$d),
        .q(reg_yp$q),
        .clock(reg_yp$clock)
    );
    top$lanes$3$feed$abc$line_b line_b(
        .clock(line_b$clock),
        .data_in(line_b$data_in),
        .write_enable(line_b$write_enable),
        .data_out(line_b$data_out),
        .last(line_b$last)
    );
    top$lanes$3$feed$abc$reg_xm reg_xm(
        .d(reg_xm$d),
        .q(reg_xm$q),
        .clock(reg_xm$clock)
    );
    top$lanes$3$feed$abc$reg_c reg_c(
        .d(reg_c$d),
        .q(reg_c$q),
        .clock(reg_c$clock)
    );
    top$lanes$3$feed$abc$line_c line_c(
        .clock(line_c$clock),
        .data_in(line_c$data_in),
        .write_enable(line_c$write_enable),
        .data_out(line_c$data_out),
        .last(line_c$last)
    );
    top$lanes$3$feed$abc$line_d line_d(
        .clock(line_d$clock),
        .data_in(line_d$data_in),
        .write_enable(line_d$write_enable),
        .data_out(line_d$data_out),
        .last(line_d$last)
    );
    top$lanes$3$feed$abc$hop_xm hop_xm(
        .d(hop_xm$d),
        .q(hop_xm$q),
        .clock(hop_xm$clock)
    );
    top$lanes$3$feed$abc$hop_ym hop_ym(
        .d(hop_ym$d),
        .q(hop_ym$q),
        .clock(hop_ym$clock)
    );
    top$lanes$3$feed$abc$hop_zm hop_zm(
        .d(hop_zm$d),
        .q(hop_zm$q),
        .clock(hop_zm$clock)
    );
    top$lanes$3$feed$abc$hop_xp hop_xp(
        .d(hop_xp$d),
        .q(hop_xp$q),
        .clock(hop_xp$clock)
    );
    top$lanes$3$feed$abc$hop_yp hop_yp(
        .d(hop_yp$d),
        .q(hop_yp$q),
        .clock(hop_yp$clock)
    );
    top$lanes$3$feed$abc$hop_zp hop_zp(
        .d(hop_zp$d),
        .q(hop_zp$q),
        .clock(hop_zp$clock)
    );
    top$lanes$3$feed$abc$prev_xm prev_xm(
        .d(prev_xm$d),
        .q(prev_xm$q),
        .clock(prev_xm$clock)
    );
    top$lanes$3$feed$abc$prev_xp prev_xp(
        .d(prev_xp$d),
        .q(prev_xp$q),
        .clock(prev_xp$clock)
    );
    top$lanes$3$feed$abc$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$3$feed$abc$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$3$feed$abc$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$3$feed$abc$last_a last_a(
        .d(last_a$d),
        .q(last_a$q),
        .clock(last_a$clock)
    );
    top$lanes$3$feed$abc$last_b last_b(
        .d(last_b$d),
        .q(last_b$q),
        .clock(last_b$clock)
    );
    top$lanes$3$feed$abc$last_d last_d(
        .d(last_d$d),
        .q(last_d$q),
        .clock(last_d$clock)
    );
    
    // Update code
    reg  [15:0] to_right_xm_pass;
    reg  [15:0] to_right_ym_pass;
    reg  [15:0] to_right_zm_pass;
    reg  [15:0] to_left_xp_pass;
    reg  [15:0] to_left_yp_pass;
    reg  [15:0] to_left_zp_pass;
    reg  [15:0] o_value_pass;
    reg  gx_neg_pass;
    reg  [15:0] gx_mag_pass;
    reg  gy_neg_pass;
    reg  [15:0] gy_mag_pass;
    reg  gz_neg_pass;
    reg  [15:0] gz_mag_pass;
    always @(*) begin
        reg_yp$clock = clock;
        reg_xm$clock = clock;
        reg_c$clock = clock;
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        last_a$clock = clock;
        last_b$clock = clock;
        last_d$clock = clock;
        reg_yp$d = reg_yp$q;
        reg_xm$d = reg_xm$q;
        reg_c$d = reg_c$q;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        last_a$d = last_a$q;
        last_b$d = last_b$q;
        last_d$d = last_d$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        last_d$d = slice_less_beam$q - 'h1;
        last_a$d = slice_less_beam$q - 'h2;
        last_b$d = beam$q - 'h1;
        line_a$last = last_a$q;
        line_b$last = last_b$q;
        line_c$last = last_b$q;
        line_d$last = last_d$q;
        line_a$clock = clock;
        line_b$clock = clock;
        line_c$clock = clock;
        line_d$clock = clock;
        line_a$data_in = value;
        line_a$write_enable = 1'b1;
        reg_yp$d = line_a$data_out;
        line_b$data_in = line_a$data_out;
        line_b$write_enable = 1'b1;
        reg_xm$d = line_b$data_out;
        reg_c$d = reg_xm$q;
        line_c$data_in = reg_xm$q;
        line_c$write_enable = 1'b1;
        line_d$data_in = line_c$data_out;
        line_d$write_enable = 1'b1;
        to_left_yp_pass = reg_yp$q;
        to_left_xp_pass = line_b$data_out;
        to_right_xm_pass = reg_xm$q;
        to_right_ym_pass = line_c$data_out;
        to_right_zm_pass = line_d$data_out;
        to_left_zp_pass = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((x & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((x & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg_pass = xp < xm;
        gx_mag_pass = xp - xm;
        if (xp < xm) begin
            gx_mag_pass = xm - xp;
        end
        gy_neg_pass = hop_yp$q < hop_ym$q;
        gy_mag_pass = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag_pass = hop_ym$q - hop_yp$q;
        end
        gz_neg_pass = hop_zp$q < hop_zm$q;
        gz_mag_pass = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag_pass = hop_zm$q - hop_zp$q;
        end
        o_value_pass = reg_c$q;
        if (~enabled) begin
            to_right_xm_pass = 'h0;
            to_right_ym_pass = 'h0;
            to_right_zm_pass = 'h0;
            to_left_xp_pass = 'h0;
            to_left_yp_pass = 'h0;
            to_left_zp_pass = 'h0;
            o_value_pass = 'h0;
            gx_mag_pass = 'h0;
            gy_mag_pass = 'h0;
            gz_mag_pass = 'h0;
            gx_neg_pass = 1'b0;
            gy_neg_pass = 1'b0;
            gz_neg_pass = 1'b0;
        end
        to_right_xm = to_right_xm_pass;
        to_right_ym = to_right_ym_pass;
        to_right_zm = to_right_zm_pass;
        to_left_xp = to_left_xp_pass;
        to_left_yp = to_left_yp_pass;
        to_left_zp = to_left_zp_pass;
        o_value = o_value_pass;
        gx_neg = gx_neg_pass;
        gx_mag = gx_mag_pass;
        gy_neg = gy_neg_pass;
        gy_mag = gy_mag_pass;
        gz_neg = gz_neg_pass;
        gz_mag = gz_mag_pass;
    end
    
endmodule // top$lanes$3$feed$abc
module top$lanes$3$feed$abc$beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$beam
module top$lanes$3$feed$abc$hop_xm(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_xm
module top$lanes$3$feed$abc$hop_xp(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_xp
module top$lanes$3$feed$abc$hop_ym(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_ym
module top$lanes$3$feed$abc$hop_yp(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_yp
module top$lanes$3$feed$abc$hop_zm(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_zm
module top$lanes$3$feed$abc$hop_zp(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$hop_zp
module top$lanes$3$feed$abc$last_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$last_a
module top$lanes$3$feed$abc$last_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$last_b
module top$lanes$3$feed$abc$last_d(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$last_d
module top$lanes$3$feed$abc$line_a(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbc;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$3$feed$abc$line_a$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$3$feed$abc$line_a$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$3$feed$abc$line_a$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$3$feed$abc$line_a$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$3$feed$abc$line_a$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$3$feed$abc$line_a$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$3$feed$abc$line_a$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$3$feed$abc$line_a$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$3$feed$abc$line_a$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$3$feed$abc$line_a$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$3$feed$abc$line_a$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$3$feed$abc$line_a
module top$lanes$3$feed$abc$line_a$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_a$bound
module top$lanes$3$feed$abc$line_a$head(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$head
module top$lanes$3$feed$abc$line_a$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_a$is_one
module top$lanes$3$feed$abc$line_a$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_a$is_short
module top$lanes$3$feed$abc$line_a$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_a$is_two
module top$lanes$3$feed$abc$line_a$one(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$one
module top$lanes$3$feed$abc$line_a$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$ptr
module top$lanes$3$feed$abc$line_a$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16316:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16316:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$3$feed$abc$line_a$ram
module top$lanes$3$feed$abc$line_a$rd(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$rd
module top$lanes$3$feed$abc$line_a$short(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$short
module top$lanes$3$feed$abc$line_a$two(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_a$two
module top$lanes$3$feed$abc$line_b(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$3$feed$abc$line_b$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$3$feed$abc$line_b$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$3$feed$abc$line_b$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$3$feed$abc$line_b$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$3$feed$abc$line_b$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$3$feed$abc$line_b$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$3$feed$abc$line_b$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$3$feed$abc$line_b$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$3$feed$abc$line_b$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$3$feed$abc$line_b$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$3$feed$abc$line_b$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$3$feed$abc$line_b
module top$lanes$3$feed$abc$line_b$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_b$bound
module top$lanes$3$feed$abc$line_b$head(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$head
module top$lanes$3$feed$abc$line_b$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_b$is_one
module top$lanes$3$feed$abc$line_b$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_b$is_short
module top$lanes$3$feed$abc$line_b$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_b$is_two
module top$lanes$3$feed$abc$line_b$one(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$one
module top$lanes$3$feed$abc$line_b$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$ptr
module top$lanes$3$feed$abc$line_b$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$3$feed$abc$line_b$ram
module top$lanes$3$feed$abc$line_b$rd(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$rd
module top$lanes$3$feed$abc$line_b$short(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$short
module top$lanes$3$feed$abc$line_b$two(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_b$two
module top$lanes$3$feed$abc$line_c(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3d;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$3$feed$abc$line_c$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$3$feed$abc$line_c$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$3$feed$abc$line_c$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$3$feed$abc$line_c$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$3$feed$abc$line_c$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$3$feed$abc$line_c$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$3$feed$abc$line_c$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$3$feed$abc$line_c$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$3$feed$abc$line_c$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$3$feed$abc$line_c$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$3$feed$abc$line_c$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$3$feed$abc$line_c
module top$lanes$3$feed$abc$line_c$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_c$bound
module top$lanes$3$feed$abc$line_c$head(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$head
module top$lanes$3$feed$abc$line_c$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_c$is_one
module top$lanes$3$feed$abc$line_c$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_c$is_short
module top$lanes$3$feed$abc$line_c$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_c$is_two
module top$lanes$3$feed$abc$line_c$one(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$one
module top$lanes$3$feed$abc$line_c$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$ptr
module top$lanes$3$feed$abc$line_c$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [7:0] mem_0_0[61:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[7:0] <= mem_0_0[read_address[5:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[5:0]] <= stored_word[7:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$3$feed$abc$line_c$ram
module top$lanes$3$feed$abc$line_c$rd(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$rd
module top$lanes$3$feed$abc$line_c$short(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$short
module top$lanes$3$feed$abc$line_c$two(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_c$two
module top$lanes$3$feed$abc$line_d(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] data_in;
    input wire  write_enable;
    output reg  [15:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h3fbd;
    localparam  has_ring = 1'b1;
    localparam  mask = 16'hff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] one$d;
    wire  [15:0] one$q;
    reg  one$clock;
    reg  [15:0] two$d;
    wire  [15:0] two$q;
    reg  two$clock;
    reg  [15:0] short$d;
    wire  [15:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$3$feed$abc$line_d$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$3$feed$abc$line_d$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$3$feed$abc$line_d$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$3$feed$abc$line_d$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$3$feed$abc$line_d$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$3$feed$abc$line_d$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$3$feed$abc$line_d$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$3$feed$abc$line_d$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$3$feed$abc$line_d$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$3$feed$abc$line_d$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$3$feed$abc$line_d$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [15:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$3$feed$abc$line_d
module top$lanes$3$feed$abc$line_d$bound(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_d$bound
module top$lanes$3$feed$abc$line_d$head(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$head
module top$lanes$3$feed$abc$line_d$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_d$is_one
module top$lanes$3$feed$abc$line_d$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_d$is_short
module top$lanes$3$feed$abc$line_d$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$line_d$is_two
module top$lanes$3$feed$abc$line_d$one(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$one
module top$lanes$3$feed$abc$line_d$ptr(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$ptr
module top$lanes$3$feed$abc$line_d$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [7:0] stored_word = {write_data[7:0]};
    (* no_rw_check *)
    reg [0:0] mem_0_0[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_1[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_2[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_3[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_4[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_5[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_6[16317:0];
    (* no_rw_check *)
    reg [0:0] mem_0_7[16317:0];
    reg [7:0] rd_0;
    reg [7:0] q_0;
    reg [7:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[0:0] <= mem_0_0[read_address[13:0]];
       rd_0[1:1] <= mem_0_1[read_address[13:0]];
       rd_0[2:2] <= mem_0_2[read_address[13:0]];
       rd_0[3:3] <= mem_0_3[read_address[13:0]];
       rd_0[4:4] <= mem_0_4[read_address[13:0]];
       rd_0[5:5] <= mem_0_5[read_address[13:0]];
       rd_0[6:6] <= mem_0_6[read_address[13:0]];
       rd_0[7:7] <= mem_0_7[read_address[13:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[13:0]] <= stored_word[0:0];
          mem_0_1[write_address[13:0]] <= stored_word[1:1];
          mem_0_2[write_address[13:0]] <= stored_word[2:2];
          mem_0_3[write_address[13:0]] <= stored_word[3:3];
          mem_0_4[write_address[13:0]] <= stored_word[4:4];
          mem_0_5[write_address[13:0]] <= stored_word[5:5];
          mem_0_6[write_address[13:0]] <= stored_word[6:6];
          mem_0_7[write_address[13:0]] <= stored_word[7:7];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[7:0]};
    end
endmodule // top$lanes$3$feed$abc$line_d$ram
module top$lanes$3$feed$abc$line_d$rd(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$rd
module top$lanes$3$feed$abc$line_d$short(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$short
module top$lanes$3$feed$abc$line_d$two(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$line_d$two
module top$lanes$3$feed$abc$prev_xm(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$prev_xm
module top$lanes$3$feed$abc$prev_xp(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$prev_xp
module top$lanes$3$feed$abc$reg_c(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$reg_c
module top$lanes$3$feed$abc$reg_xm(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$reg_xm
module top$lanes$3$feed$abc$reg_yp(d,q,clock);
    
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
          
endmodule // top$lanes$3$feed$abc$reg_yp
module top$lanes$3$feed$abc$slice(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$slice
module top$lanes$3$feed$abc$slice_less_beam(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$feed$abc$slice_less_beam
