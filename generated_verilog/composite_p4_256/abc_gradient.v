module top$lanes$0$feed$abc(clock,now,valid,value,x,y,pad,invalid,dx_neg,dx_mag,dy_neg,dy_mag,sr,er,at_edge,face,base_x,base_y,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  sr;
    input wire  er;
    input wire  at_edge;
    input wire  [2:0] face;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
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
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  off_centre = 16'hc000;
    localparam  off_xm = 16'hc001;
    localparam  off_ym = 16'hbfc1;
    localparam  off_zm = 16'h8001;
    localparam  off_xp = 16'hc002;
    localparam  off_yp = 16'hc041;
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] centre$read_address;
    reg  centre$read_clock;
    wire  [122:0] centre$read_data;
    reg  [15:0] centre$write_address;
    reg  centre$write_clock;
    reg  [122:0] centre$write_data;
    reg  centre$write_enable;
    reg  [15:0] ring_xm$read_address;
    reg  ring_xm$read_clock;
    wire  [15:0] ring_xm$read_data;
    reg  [15:0] ring_xm$write_address;
    reg  ring_xm$write_clock;
    reg  [15:0] ring_xm$write_data;
    reg  ring_xm$write_enable;
    reg  [15:0] ring_ym$read_address;
    reg  ring_ym$read_clock;
    wire  [15:0] ring_ym$read_data;
    reg  [15:0] ring_ym$write_address;
    reg  ring_ym$write_clock;
    reg  [15:0] ring_ym$write_data;
    reg  ring_ym$write_enable;
    reg  [15:0] ring_zm$read_address;
    reg  ring_zm$read_clock;
    wire  [15:0] ring_zm$read_data;
    reg  [15:0] ring_zm$write_address;
    reg  ring_zm$write_clock;
    reg  [15:0] ring_zm$write_data;
    reg  ring_zm$write_enable;
    reg  [15:0] ring_xp$read_address;
    reg  ring_xp$read_clock;
    wire  [15:0] ring_xp$read_data;
    reg  [15:0] ring_xp$write_address;
    reg  ring_xp$write_clock;
    reg  [15:0] ring_xp$write_data;
    reg  ring_xp$write_enable;
    reg  [15:0] ring_yp$read_address;
    reg  ring_yp$read_clock;
    wire  [15:0] ring_yp$read_data;
    reg  [15:0] ring_yp$write_address;
    reg  ring_yp$write_clock;
    reg  [15:0] ring_yp$write_data;
    reg  ring_yp$write_enable;
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
    
    // Local signals
    reg  [122:0] word;
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$0$feed$abc$centre centre(
        .read_address(centre$read_address),
        .read_clock(centre$read_clock),
        .read_data(centre$read_data),
        .write_address(centre$write_address),
        .write_clock(centre$write_clock),
        .write_data(centre$write_data),
        .write_enable(centre$write_enable)
    );
    top$lanes$0$feed$abc$ring_xm ring_xm(
        .read_address(ring_xm$read_address),
        .read_clock(ring_xm$read_clock),
        .read_data(ring_xm$read_data),
        .write_address(ring_xm$write_address),
        .write_clock(ring_xm$write_clock),
        .write_data(ring_xm$write_data),
        .write_enable(ring_xm$write_enable)
    );
    top$lanes$0$feed$abc$ring_ym ring_ym(
        .read_address(ring_ym$read_address),
        .read_clock(ring_ym$read_clock),
        .read_data(ring_ym$read_data),
        .write_address(ring_ym$write_address),
        .write_clock(ring_ym$write_clock),
        .write_data(ring_ym$write_data),
        .write_enable(ring_ym$write_enable)
    );
    top$lanes$0$feed$abc$ring_zm ring_zm(
        .read_address(ring_zm$read_address),
        .read_clock(ring_zm$read_clock),
        .read_data(ring_zm$read_data),
        .write_address(ring_zm$write_address),
        .write_clock(ring_zm$write_clock),
        .write_data(ring_zm$write_data),
        .write_enable(ring_zm$write_enable)
    );
    top$lanes$0$feed$abc$ring_xp ring_xp(
        .read_address(ring_xp$read_address),
        .read_clock(ring_xp$read_clock),
        .read_data(ring_xp$read_data),
        .write_address(ring_xp$write_address),
        .write_clock(ring_xp$write_clock),
        .write_data(ring_xp$write_data),
        .write_enable(ring_xp$write_enable)
    );
    top$lanes$0$feed$abc$ring_yp ring_yp(
        .read_address(ring_yp$read_address),
        .read_clock(ring_yp$read_clock),
        .read_data(ring_yp$read_data),
        .write_address(ring_yp$write_address),
        .write_clock(ring_yp$write_clock),
        .write_data(ring_yp$write_data),
        .write_enable(ring_yp$write_enable)
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
    
    // Update code
    always @(*) begin
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        centre$read_clock = clock;
        centre$write_clock = clock;
        ring_xm$read_clock = clock;
        ring_xm$write_clock = clock;
        ring_ym$read_clock = clock;
        ring_ym$write_clock = clock;
        ring_zm$read_clock = clock;
        ring_zm$write_clock = clock;
        ring_xp$read_clock = clock;
        ring_xp$write_clock = clock;
        ring_yp$read_clock = clock;
        ring_yp$write_clock = clock;
        word = 123'(value) | (123'(x) << 'h10) | (123'(y) << 'h20) | (123'(base_x) << 'h30) | (123'(base_y) << 'h40) | (123'(valid) << 'h50) | (123'(pad) << 'h51) | (123'(sr) << 'h52) | (123'(er) << 'h53) | (123'(at_edge) << 'h54) | (123'(face) << 'h55) | (123'(dx_neg) << 'h58) | (123'(dx_mag) << 'h59) | (123'(dy_neg) << 'h69) | (123'(dy_mag) << 'h6a) | (123'(invalid) << 'h7a);
        centre$write_address = now;
        centre$write_data = word;
        centre$write_enable = 1'b1;
        ring_xm$write_address = now;
        ring_xm$write_data = value;
        ring_xm$write_enable = 1'b1;
        ring_ym$write_address = now;
        ring_ym$write_data = value;
        ring_ym$write_enable = 1'b1;
        ring_zm$write_address = now;
        ring_zm$write_data = value;
        ring_zm$write_enable = 1'b1;
        ring_xp$write_address = now;
        ring_xp$write_data = value;
        ring_xp$write_enable = 1'b1;
        ring_yp$write_address = now;
        ring_yp$write_data = value;
        ring_yp$write_enable = 1'b1;
        centre$read_address = now + off_centre;
        ring_xm$read_address = now + off_xm;
        ring_ym$read_address = now + off_ym;
        ring_zm$read_address = now + off_zm;
        ring_xp$read_address = now + off_xp;
        ring_yp$read_address = now + off_yp;
        to_right_xm = ring_xm$read_data;
        to_right_ym = ring_ym$read_data;
        to_right_zm = ring_zm$read_data;
        to_left_xp = ring_xp$read_data;
        to_left_yp = ring_yp$read_data;
        to_left_zp = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg = xp < xm;
        gx_mag = xp - xm;
        if (xp < xm) begin
            gx_mag = xm - xp;
        end
        gy_neg = hop_yp$q < hop_ym$q;
        gy_mag = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag = hop_ym$q - hop_yp$q;
        end
        gz_neg = hop_zp$q < hop_zm$q;
        gz_mag = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag = hop_zm$q - hop_zp$q;
        end
        o_value = centre$read_data[('h0)+:(16)];
        o_x = centre$read_data[('h10)+:(16)];
        o_y = centre$read_data[('h20)+:(16)];
        o_base_x = centre$read_data[('h30)+:(16)];
        o_base_y = centre$read_data[('h40)+:(16)];
        o_valid = centre$read_data['h50];
        o_pad = centre$read_data['h51];
        o_sr = centre$read_data['h52];
        o_er = centre$read_data['h53];
        o_edge = centre$read_data['h54];
        o_face = centre$read_data[('h55)+:(3)];
        o_dx_neg = centre$read_data['h58];
        o_dx_mag = centre$read_data[('h59)+:(16)];
        o_dy_neg = centre$read_data['h69];
        o_dy_mag = centre$read_data[('h6a)+:(16)];
        o_invalid = centre$read_data['h7a];
        if (~enabled) begin
            to_right_xm = 'h0;
            to_right_ym = 'h0;
            to_right_zm = 'h0;
            to_left_xp = 'h0;
            to_left_yp = 'h0;
            to_left_zp = 'h0;
            o_value = 'h0;
            o_x = 'h0;
            o_y = 'h0;
            o_dx_mag = 'h0;
            o_dy_mag = 'h0;
            o_base_x = 'h0;
            o_base_y = 'h0;
            gx_mag = 'h0;
            gy_mag = 'h0;
            gz_mag = 'h0;
            o_valid = 1'b0;
            o_pad = 1'b0;
            o_invalid = 1'b0;
            o_dx_neg = 1'b0;
            o_dy_neg = 1'b0;
            o_sr = 1'b0;
            o_er = 1'b0;
            o_edge = 1'b0;
            gx_neg = 1'b0;
            gy_neg = 1'b0;
            gz_neg = 1'b0;
            o_face = 'h0;
        end
    end
    
endmodule // top$lanes$0$feed$abc
module top$lanes$0$feed$abc$centre(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [122:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [122:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [122:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[15:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= write_data;
       end
    end
endmodule // top$lanes$0$feed$abc$centre
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
module top$lanes$0$feed$abc$ring_xm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$feed$abc$ring_xm
module top$lanes$0$feed$abc$ring_xp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$feed$abc$ring_xp
module top$lanes$0$feed$abc$ring_ym(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$feed$abc$ring_ym
module top$lanes$0$feed$abc$ring_yp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$feed$abc$ring_yp
module top$lanes$0$feed$abc$ring_zm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$feed$abc$ring_zm
module top$lanes$1$feed$abc(clock,now,valid,value,x,y,pad,invalid,dx_neg,dx_mag,dy_neg,dy_mag,sr,er,at_edge,face,base_x,base_y,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  sr;
    input wire  er;
    input wire  at_edge;
    input wire  [2:0] face;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
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
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  off_centre = 16'hc000;
    localparam  off_xm = 16'hc001;
    localparam  off_ym = 16'hbfc1;
    localparam  off_zm = 16'h8001;
    localparam  off_xp = 16'hc002;
    localparam  off_yp = 16'hc041;
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] centre$read_address;
    reg  centre$read_clock;
    wire  [122:0] centre$read_data;
    reg  [15:0] centre$write_address;
    reg  centre$write_clock;
    reg  [122:0] centre$write_data;
    reg  centre$write_enable;
    reg  [15:0] ring_xm$read_address;
    reg  ring_xm$read_clock;
    wire  [15:0] ring_xm$read_data;
    reg  [15:0] ring_xm$write_address;
    reg  ring_xm$write_clock;
    reg  [15:0] ring_xm$write_data;
    reg  ring_xm$write_enable;
    reg  [15:0] ring_ym$read_address;
    reg  ring_ym$read_clock;
    wire  [15:0] ring_ym$read_data;
    reg  [15:0] ring_ym$write_address;
    reg  ring_ym$write_clock;
    reg  [15:0] ring_ym$write_data;
    reg  ring_ym$write_enable;
    reg  [15:0] ring_zm$read_address;
    reg  ring_zm$read_clock;
    wire  [15:0] ring_zm$read_data;
    reg  [15:0] ring_zm$write_address;
    reg  ring_zm$write_clock;
    reg  [15:0] ring_zm$write_data;
    reg  ring_zm$write_enable;
    reg  [15:0] ring_xp$read_address;
    reg  ring_xp$read_clock;
    wire  [15:0] ring_xp$read_data;
    reg  [15:0] ring_xp$write_address;
    reg  ring_xp$write_clock;
    reg  [15:0] ring_xp$write_data;
    reg  ring_xp$write_enable;
    reg  [15:0] ring_yp$read_address;
    reg  ring_yp$read_clock;
    wire  [15:0] ring_yp$read_data;
    reg  [15:0] ring_yp$write_address;
    reg  ring_yp$write_clock;
    reg  [15:0] ring_yp$write_data;
    reg  ring_yp$write_enable;
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
    
    // Local signals
    reg  [122:0] word;
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$1$feed$abc$centre centre(
        .read_address(centre$read_address),
        .read_clock(centre$read_clock),
        .read_data(centre$read_data),
        .write_address(centre$write_address),
        .write_clock(centre$write_clock),
        .write_data(centre$write_data),
        .write_enable(centre$write_enable)
    );
    top$lanes$1$feed$abc$ring_xm ring_xm(
        .read_address(ring_xm$read_address),
        .read_clock(ring_xm$read_clock),
        .read_data(ring_xm$read_data),
        .write_address(ring_xm$write_address),
        .write_clock(ring_xm$write_clock),
        .write_data(ring_xm$write_data),
        .write_enable(ring_xm$write_enable)
    );
    top$lanes$1$feed$abc$ring_ym ring_ym(
        .read_address(ring_ym$read_address),
        .read_clock(ring_ym$read_clock),
        .read_data(ring_ym$read_data),
        .write_address(ring_ym$write_address),
        .write_clock(ring_ym$write_clock),
        .write_data(ring_ym$write_data),
        .write_enable(ring_ym$write_enable)
    );
    top$lanes$1$feed$abc$ring_zm ring_zm(
        .read_address(ring_zm$read_address),
        .read_clock(ring_zm$read_clock),
        .read_data(ring_zm$read_data),
        .write_address(ring_zm$write_address),
        .write_clock(ring_zm$write_clock),
        .write_data(ring_zm$write_data),
        .write_enable(ring_zm$write_enable)
    );
    top$lanes$1$feed$abc$ring_xp ring_xp(
        .read_address(ring_xp$read_address),
        .read_clock(ring_xp$read_clock),
        .read_data(ring_xp$read_data),
        .write_address(ring_xp$write_address),
        .write_clock(ring_xp$write_clock),
        .write_data(ring_xp$write_data),
        .write_enable(ring_xp$write_enable)
    );
    top$lanes$1$feed$abc$ring_yp ring_yp(
        .read_address(ring_yp$read_address),
        .read_clock(ring_yp$read_clock),
        .read_data(ring_yp$read_data),
        .write_address(ring_yp$write_address),
        .write_clock(ring_yp$write_clock),
        .write_data(ring_yp$write_data),
        .write_enable(ring_yp$write_enable)
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
    
    // Update code
    always @(*) begin
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        centre$read_clock = clock;
        centre$write_clock = clock;
        ring_xm$read_clock = clock;
        ring_xm$write_clock = clock;
        ring_ym$read_clock = clock;
        ring_ym$write_clock = clock;
        ring_zm$read_clock = clock;
        ring_zm$write_clock = clock;
        ring_xp$read_clock = clock;
        ring_xp$write_clock = clock;
        ring_yp$read_clock = clock;
        ring_yp$write_clock = clock;
        word = 123'(value) | (123'(x) << 'h10) | (123'(y) << 'h20) | (123'(base_x) << 'h30) | (123'(base_y) << 'h40) | (123'(valid) << 'h50) | (123'(pad) << 'h51) | (123'(sr) << 'h52) | (123'(er) << 'h53) | (123'(at_edge) << 'h54) | (123'(face) << 'h55) | (123'(dx_neg) << 'h58) | (123'(dx_mag) << 'h59) | (123'(dy_neg) << 'h69) | (123'(dy_mag) << 'h6a) | (123'(invalid) << 'h7a);
        centre$write_address = now;
        centre$write_data = word;
        centre$write_enable = 1'b1;
        ring_xm$write_address = now;
        ring_xm$write_data = value;
        ring_xm$write_enable = 1'b1;
        ring_ym$write_address = now;
        ring_ym$write_data = value;
        ring_ym$write_enable = 1'b1;
        ring_zm$write_address = now;
        ring_zm$write_data = value;
        ring_zm$write_enable = 1'b1;
        ring_xp$write_address = now;
        ring_xp$write_data = value;
        ring_xp$write_enable = 1'b1;
        ring_yp$write_address = now;
        ring_yp$write_data = value;
        ring_yp$write_enable = 1'b1;
        centre$read_address = now + off_centre;
        ring_xm$read_address = now + off_xm;
        ring_ym$read_address = now + off_ym;
        ring_zm$read_address = now + off_zm;
        ring_xp$read_address = now + off_xp;
        ring_yp$read_address = now + off_yp;
        to_right_xm = ring_xm$read_data;
        to_right_ym = ring_ym$read_data;
        to_right_zm = ring_zm$read_data;
        to_left_xp = ring_xp$read_data;
        to_left_yp = ring_yp$read_data;
        to_left_zp = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg = xp < xm;
        gx_mag = xp - xm;
        if (xp < xm) begin
            gx_mag = xm - xp;
        end
        gy_neg = hop_yp$q < hop_ym$q;
        gy_mag = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag = hop_ym$q - hop_yp$q;
        end
        gz_neg = hop_zp$q < hop_zm$q;
        gz_mag = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag = hop_zm$q - hop_zp$q;
        end
        o_value = centre$read_data[('h0)+:(16)];
        o_x = centre$read_data[('h10)+:(16)];
        o_y = centre$read_data[('h20)+:(16)];
        o_base_x = centre$read_data[('h30)+:(16)];
        o_base_y = centre$read_data[('h40)+:(16)];
        o_valid = centre$read_data['h50];
        o_pad = centre$read_data['h51];
        o_sr = centre$read_data['h52];
        o_er = centre$read_data['h53];
        o_edge = centre$read_data['h54];
        o_face = centre$read_data[('h55)+:(3)];
        o_dx_neg = centre$read_data['h58];
        o_dx_mag = centre$read_data[('h59)+:(16)];
        o_dy_neg = centre$read_data['h69];
        o_dy_mag = centre$read_data[('h6a)+:(16)];
        o_invalid = centre$read_data['h7a];
        if (~enabled) begin
            to_right_xm = 'h0;
            to_right_ym = 'h0;
            to_right_zm = 'h0;
            to_left_xp = 'h0;
            to_left_yp = 'h0;
            to_left_zp = 'h0;
            o_value = 'h0;
            o_x = 'h0;
            o_y = 'h0;
            o_dx_mag = 'h0;
            o_dy_mag = 'h0;
            o_base_x = 'h0;
            o_base_y = 'h0;
            gx_mag = 'h0;
            gy_mag = 'h0;
            gz_mag = 'h0;
            o_valid = 1'b0;
            o_pad = 1'b0;
            o_invalid = 1'b0;
            o_dx_neg = 1'b0;
            o_dy_neg = 1'b0;
            o_sr = 1'b0;
            o_er = 1'b0;
            o_edge = 1'b0;
            gx_neg = 1'b0;
            gy_neg = 1'b0;
            gz_neg = 1'b0;
            o_face = 'h0;
        end
    end
    
endmodule // top$lanes$1$feed$abc
module top$lanes$1$feed$abc$centre(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [122:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [122:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [122:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[15:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= write_data;
       end
    end
endmodule // top$lanes$1$feed$abc$centre
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
module top$lanes$1$feed$abc$ring_xm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$feed$abc$ring_xm
module top$lanes$1$feed$abc$ring_xp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$feed$abc$ring_xp
module top$lanes$1$feed$abc$ring_ym(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$feed$abc$ring_ym
module top$lanes$1$feed$abc$ring_yp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$feed$abc$ring_yp
module top$lanes$1$feed$abc$ring_zm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$feed$abc$ring_zm
module top$lanes$2$feed$abc(clock,now,valid,value,x,y,pad,invalid,dx_neg,dx_mag,dy_neg,dy_mag,sr,er,at_edge,face,base_x,base_y,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  sr;
    input wire  er;
    input wire  at_edge;
    input wire  [2:0] face;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
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
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  off_centre = 16'hc000;
    localparam  off_xm = 16'hc001;
    localparam  off_ym = 16'hbfc1;
    localparam  off_zm = 16'h8001;
    localparam  off_xp = 16'hc002;
    localparam  off_yp = 16'hc041;
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] centre$read_address;
    reg  centre$read_clock;
    wire  [122:0] centre$read_data;
    reg  [15:0] centre$write_address;
    reg  centre$write_clock;
    reg  [122:0] centre$write_data;
    reg  centre$write_enable;
    reg  [15:0] ring_xm$read_address;
    reg  ring_xm$read_clock;
    wire  [15:0] ring_xm$read_data;
    reg  [15:0] ring_xm$write_address;
    reg  ring_xm$write_clock;
    reg  [15:0] ring_xm$write_data;
    reg  ring_xm$write_enable;
    reg  [15:0] ring_ym$read_address;
    reg  ring_ym$read_clock;
    wire  [15:0] ring_ym$read_data;
    reg  [15:0] ring_ym$write_address;
    reg  ring_ym$write_clock;
    reg  [15:0] ring_ym$write_data;
    reg  ring_ym$write_enable;
    reg  [15:0] ring_zm$read_address;
    reg  ring_zm$read_clock;
    wire  [15:0] ring_zm$read_data;
    reg  [15:0] ring_zm$write_address;
    reg  ring_zm$write_clock;
    reg  [15:0] ring_zm$write_data;
    reg  ring_zm$write_enable;
    reg  [15:0] ring_xp$read_address;
    reg  ring_xp$read_clock;
    wire  [15:0] ring_xp$read_data;
    reg  [15:0] ring_xp$write_address;
    reg  ring_xp$write_clock;
    reg  [15:0] ring_xp$write_data;
    reg  ring_xp$write_enable;
    reg  [15:0] ring_yp$read_address;
    reg  ring_yp$read_clock;
    wire  [15:0] ring_yp$read_data;
    reg  [15:0] ring_yp$write_address;
    reg  ring_yp$write_clock;
    reg  [15:0] ring_yp$write_data;
    reg  ring_yp$write_enable;
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
    
    // Local signals
    reg  [122:0] word;
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$2$feed$abc$centre centre(
        .read_address(centre$read_address),
        .read_clock(centre$read_clock),
        .read_data(centre$read_data),
        .write_address(centre$write_address),
        .write_clock(centre$write_clock),
        .write_data(centre$write_data),
        .write_enable(centre$write_enable)
    );
    top$lanes$2$feed$abc$ring_xm ring_xm(
        .read_address(ring_xm$read_address),
        .read_clock(ring_xm$read_clock),
        .read_data(ring_xm$read_data),
        .write_address(ring_xm$write_address),
        .write_clock(ring_xm$write_clock),
        .write_data(ring_xm$write_data),
        .write_enable(ring_xm$write_enable)
    );
    top$lanes$2$feed$abc$ring_ym ring_ym(
        .read_address(ring_ym$read_address),
        .read_clock(ring_ym$read_clock),
        .read_data(ring_ym$read_data),
        .write_address(ring_ym$write_address),
        .write_clock(ring_ym$write_clock),
        .write_data(ring_ym$write_data),
        .write_enable(ring_ym$write_enable)
    );
    top$lanes$2$feed$abc$ring_zm ring_zm(
        .read_address(ring_zm$read_address),
        .read_clock(ring_zm$read_clock),
        .read_data(ring_zm$read_data),
        .write_address(ring_zm$write_address),
        .write_clock(ring_zm$write_clock),
        .write_data(ring_zm$write_data),
        .write_enable(ring_zm$write_enable)
    );
    top$lanes$2$feed$abc$ring_xp ring_xp(
        .read_address(ring_xp$read_address),
        .read_clock(ring_xp$read_clock),
        .read_data(ring_xp$read_data),
        .write_address(ring_xp$write_address),
        .write_clock(ring_xp$write_clock),
        .write_data(ring_xp$write_data),
        .write_enable(ring_xp$write_enable)
    );
    top$lanes$2$feed$abc$ring_yp ring_yp(
        .read_address(ring_yp$read_address),
        .read_clock(ring_yp$read_clock),
        .read_data(ring_yp$read_data),
        .write_address(ring_yp$write_address),
        .write_clock(ring_yp$write_clock),
        .write_data(ring_yp$write_data),
        .write_enable(ring_yp$write_enable)
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
    
    // Update code
    always @(*) begin
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        centre$read_clock = clock;
        centre$write_clock = clock;
        ring_xm$read_clock = clock;
        ring_xm$write_clock = clock;
        ring_ym$read_clock = clock;
        ring_ym$write_clock = clock;
        ring_zm$read_clock = clock;
        ring_zm$write_clock = clock;
        ring_xp$read_clock = clock;
        ring_xp$write_clock = clock;
        ring_yp$read_clock = clock;
        ring_yp$write_clock = clock;
        word = 123'(value) | (123'(x) << 'h10) | (123'(y) << 'h20) | (123'(base_x) << 'h30) | (123'(base_y) << 'h40) | (123'(valid) << 'h50) | (123'(pad) << 'h51) | (123'(sr) << 'h52) | (123'(er) << 'h53) | (123'(at_edge) << 'h54) | (123'(face) << 'h55) | (123'(dx_neg) << 'h58) | (123'(dx_mag) << 'h59) | (123'(dy_neg) << 'h69) | (123'(dy_mag) << 'h6a) | (123'(invalid) << 'h7a);
        centre$write_address = now;
        centre$write_data = word;
        centre$write_enable = 1'b1;
        ring_xm$write_address = now;
        ring_xm$write_data = value;
        ring_xm$write_enable = 1'b1;
        ring_ym$write_address = now;
        ring_ym$write_data = value;
        ring_ym$write_enable = 1'b1;
        ring_zm$write_address = now;
        ring_zm$write_data = value;
        ring_zm$write_enable = 1'b1;
        ring_xp$write_address = now;
        ring_xp$write_data = value;
        ring_xp$write_enable = 1'b1;
        ring_yp$write_address = now;
        ring_yp$write_data = value;
        ring_yp$write_enable = 1'b1;
        centre$read_address = now + off_centre;
        ring_xm$read_address = now + off_xm;
        ring_ym$read_address = now + off_ym;
        ring_zm$read_address = now + off_zm;
        ring_xp$read_address = now + off_xp;
        ring_yp$read_address = now + off_yp;
        to_right_xm = ring_xm$read_data;
        to_right_ym = ring_ym$read_data;
        to_right_zm = ring_zm$read_data;
        to_left_xp = ring_xp$read_data;
        to_left_yp = ring_yp$read_data;
        to_left_zp = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg = xp < xm;
        gx_mag = xp - xm;
        if (xp < xm) begin
            gx_mag = xm - xp;
        end
        gy_neg = hop_yp$q < hop_ym$q;
        gy_mag = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag = hop_ym$q - hop_yp$q;
        end
        gz_neg = hop_zp$q < hop_zm$q;
        gz_mag = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag = hop_zm$q - hop_zp$q;
        end
        o_value = centre$read_data[('h0)+:(16)];
        o_x = centre$read_data[('h10)+:(16)];
        o_y = centre$read_data[('h20)+:(16)];
        o_base_x = centre$read_data[('h30)+:(16)];
        o_base_y = centre$read_data[('h40)+:(16)];
        o_valid = centre$read_data['h50];
        o_pad = centre$read_data['h51];
        o_sr = centre$read_data['h52];
        o_er = centre$read_data['h53];
        o_edge = centre$read_data['h54];
        o_face = centre$read_data[('h55)+:(3)];
        o_dx_neg = centre$read_data['h58];
        o_dx_mag = centre$read_data[('h59)+:(16)];
        o_dy_neg = centre$read_data['h69];
        o_dy_mag = centre$read_data[('h6a)+:(16)];
        o_invalid = centre$read_data['h7a];
        if (~enabled) begin
            to_right_xm = 'h0;
            to_right_ym = 'h0;
            to_right_zm = 'h0;
            to_left_xp = 'h0;
            to_left_yp = 'h0;
            to_left_zp = 'h0;
            o_value = 'h0;
            o_x = 'h0;
            o_y = 'h0;
            o_dx_mag = 'h0;
            o_dy_mag = 'h0;
            o_base_x = 'h0;
            o_base_y = 'h0;
            gx_mag = 'h0;
            gy_mag = 'h0;
            gz_mag = 'h0;
            o_valid = 1'b0;
            o_pad = 1'b0;
            o_invalid = 1'b0;
            o_dx_neg = 1'b0;
            o_dy_neg = 1'b0;
            o_sr = 1'b0;
            o_er = 1'b0;
            o_edge = 1'b0;
            gx_neg = 1'b0;
            gy_neg = 1'b0;
            gz_neg = 1'b0;
            o_face = 'h0;
        end
    end
    
endmodule // top$lanes$2$feed$abc
module top$lanes$2$feed$abc$centre(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [122:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [122:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [122:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[15:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= write_data;
       end
    end
endmodule // top$lanes$2$feed$abc$centre
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
module top$lanes$2$feed$abc$ring_xm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$feed$abc$ring_xm
module top$lanes$2$feed$abc$ring_xp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$feed$abc$ring_xp
module top$lanes$2$feed$abc$ring_ym(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$feed$abc$ring_ym
module top$lanes$2$feed$abc$ring_yp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$feed$abc$ring_yp
module top$lanes$2$feed$abc$ring_zm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$feed$abc$ring_zm
module top$lanes$3$feed$abc(clock,now,valid,value,x,y,pad,invalid,dx_neg,dx_mag,dy_neg,dy_mag,sr,er,at_edge,face,base_x,base_y,from_left_xm,from_left_ym,from_left_zm,from_right_xp,from_right_yp,from_right_zp,to_right_xm,to_right_ym,to_right_zm,to_left_xp,to_left_yp,to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  sr;
    input wire  er;
    input wire  at_edge;
    input wire  [2:0] face;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
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
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  off_centre = 16'hc000;
    localparam  off_xm = 16'hc001;
    localparam  off_ym = 16'hbfc1;
    localparam  off_zm = 16'h8001;
    localparam  off_xp = 16'hc002;
    localparam  off_yp = 16'hc041;
    localparam  p_mask = 16'h3;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] centre$read_address;
    reg  centre$read_clock;
    wire  [122:0] centre$read_data;
    reg  [15:0] centre$write_address;
    reg  centre$write_clock;
    reg  [122:0] centre$write_data;
    reg  centre$write_enable;
    reg  [15:0] ring_xm$read_address;
    reg  ring_xm$read_clock;
    wire  [15:0] ring_xm$read_data;
    reg  [15:0] ring_xm$write_address;
    reg  ring_xm$write_clock;
    reg  [15:0] ring_xm$write_data;
    reg  ring_xm$write_enable;
    reg  [15:0] ring_ym$read_address;
    reg  ring_ym$read_clock;
    wire  [15:0] ring_ym$read_data;
    reg  [15:0] ring_ym$write_address;
    reg  ring_ym$write_clock;
    reg  [15:0] ring_ym$write_data;
    reg  ring_ym$write_enable;
    reg  [15:0] ring_zm$read_address;
    reg  ring_zm$read_clock;
    wire  [15:0] ring_zm$read_data;
    reg  [15:0] ring_zm$write_address;
    reg  ring_zm$write_clock;
    reg  [15:0] ring_zm$write_data;
    reg  ring_zm$write_enable;
    reg  [15:0] ring_xp$read_address;
    reg  ring_xp$read_clock;
    wire  [15:0] ring_xp$read_data;
    reg  [15:0] ring_xp$write_address;
    reg  ring_xp$write_clock;
    reg  [15:0] ring_xp$write_data;
    reg  ring_xp$write_enable;
    reg  [15:0] ring_yp$read_address;
    reg  ring_yp$read_clock;
    wire  [15:0] ring_yp$read_data;
    reg  [15:0] ring_yp$write_address;
    reg  ring_yp$write_clock;
    reg  [15:0] ring_yp$write_data;
    reg  ring_yp$write_enable;
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
    
    // Local signals
    reg  [122:0] word;
    reg  [15:0] xm;
    reg  [15:0] xp;
    
    // Sub module instances
    top$lanes$3$feed$abc$centre centre(
        .read_address(centre$read_address),
        .read_clock(centre$read_clock),
        .read_data(centre$read_data),
        .write_address(centre$write_address),
        .write_clock(centre$write_clock),
        .write_data(centre$write_data),
        .write_enable(centre$write_enable)
    );
    top$lanes$3$feed$abc$ring_xm ring_xm(
        .read_address(ring_xm$read_address),
        .read_clock(ring_xm$read_clock),
        .read_data(ring_xm$read_data),
        .write_address(ring_xm$write_address),
        .write_clock(ring_xm$write_clock),
        .write_data(ring_xm$write_data),
        .write_enable(ring_xm$write_enable)
    );
    top$lanes$3$feed$abc$ring_ym ring_ym(
        .read_address(ring_ym$read_address),
        .read_clock(ring_ym$read_clock),
        .read_data(ring_ym$read_data),
        .write_address(ring_ym$write_address),
        .write_clock(ring_ym$write_clock),
        .write_data(ring_ym$write_data),
        .write_enable(ring_ym$write_enable)
    );
    top$lanes$3$feed$abc$ring_zm ring_zm(
        .read_address(ring_zm$read_address),
        .read_clock(ring_zm$read_clock),
        .read_data(ring_zm$read_data),
        .write_address(ring_zm$write_address),
        .write_clock(ring_zm$write_clock),
        .write_data(ring_zm$write_data),
        .write_enable(ring_zm$write_enable)
    );
    top$lanes$3$feed$abc$ring_xp ring_xp(
        .read_address(ring_xp$read_address),
        .read_clock(ring_xp$read_clock),
        .read_data(ring_xp$read_data),
        .write_address(ring_xp$write_address),
        .write_clock(ring_xp$write_clock),
        .write_data(ring_xp$write_data),
        .write_enable(ring_xp$write_enable)
    );
    top$lanes$3$feed$abc$ring_yp ring_yp(
        .read_address(ring_yp$read_address),
        .read_clock(ring_yp$read_clock),
        .read_data(ring_yp$read_data),
        .write_address(ring_yp$write_address),
        .write_clock(ring_yp$write_clock),
        .write_data(ring_yp$write_data),
        .write_enable(ring_yp$write_enable)
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
    
    // Update code
    always @(*) begin
        hop_xm$clock = clock;
        hop_ym$clock = clock;
        hop_zm$clock = clock;
        hop_xp$clock = clock;
        hop_yp$clock = clock;
        hop_zp$clock = clock;
        prev_xm$clock = clock;
        prev_xp$clock = clock;
        hop_xm$d = hop_xm$q;
        hop_ym$d = hop_ym$q;
        hop_zm$d = hop_zm$q;
        hop_xp$d = hop_xp$q;
        hop_yp$d = hop_yp$q;
        hop_zp$d = hop_zp$q;
        prev_xm$d = prev_xm$q;
        prev_xp$d = prev_xp$q;
        centre$read_clock = clock;
        centre$write_clock = clock;
        ring_xm$read_clock = clock;
        ring_xm$write_clock = clock;
        ring_ym$read_clock = clock;
        ring_ym$write_clock = clock;
        ring_zm$read_clock = clock;
        ring_zm$write_clock = clock;
        ring_xp$read_clock = clock;
        ring_xp$write_clock = clock;
        ring_yp$read_clock = clock;
        ring_yp$write_clock = clock;
        word = 123'(value) | (123'(x) << 'h10) | (123'(y) << 'h20) | (123'(base_x) << 'h30) | (123'(base_y) << 'h40) | (123'(valid) << 'h50) | (123'(pad) << 'h51) | (123'(sr) << 'h52) | (123'(er) << 'h53) | (123'(at_edge) << 'h54) | (123'(face) << 'h55) | (123'(dx_neg) << 'h58) | (123'(dx_mag) << 'h59) | (123'(dy_neg) << 'h69) | (123'(dy_mag) << 'h6a) | (123'(invalid) << 'h7a);
        centre$write_address = now;
        centre$write_data = word;
        centre$write_enable = 1'b1;
        ring_xm$write_address = now;
        ring_xm$write_data = value;
        ring_xm$write_enable = 1'b1;
        ring_ym$write_address = now;
        ring_ym$write_data = value;
        ring_ym$write_enable = 1'b1;
        ring_zm$write_address = now;
        ring_zm$write_data = value;
        ring_zm$write_enable = 1'b1;
        ring_xp$write_address = now;
        ring_xp$write_data = value;
        ring_xp$write_enable = 1'b1;
        ring_yp$write_address = now;
        ring_yp$write_data = value;
        ring_yp$write_enable = 1'b1;
        centre$read_address = now + off_centre;
        ring_xm$read_address = now + off_xm;
        ring_ym$read_address = now + off_ym;
        ring_zm$read_address = now + off_zm;
        ring_xp$read_address = now + off_xp;
        ring_yp$read_address = now + off_yp;
        to_right_xm = ring_xm$read_data;
        to_right_ym = ring_ym$read_data;
        to_right_zm = ring_zm$read_data;
        to_left_xp = ring_xp$read_data;
        to_left_yp = ring_yp$read_data;
        to_left_zp = value;
        hop_xm$d = from_left_xm;
        hop_ym$d = from_left_ym;
        hop_zm$d = from_left_zm;
        hop_xp$d = from_right_xp;
        hop_yp$d = from_right_yp;
        hop_zp$d = from_right_zp;
        prev_xm$d = hop_xm$q;
        prev_xp$d = hop_xp$q;
        xm = hop_xm$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == 'h0) begin
            xm = prev_xm$q;
        end
        xp = prev_xp$q;
        if ((centre$read_data[('h10)+:(16)] & p_mask) == p_mask) begin
            xp = hop_xp$q;
        end
        gx_neg = xp < xm;
        gx_mag = xp - xm;
        if (xp < xm) begin
            gx_mag = xm - xp;
        end
        gy_neg = hop_yp$q < hop_ym$q;
        gy_mag = hop_yp$q - hop_ym$q;
        if (hop_yp$q < hop_ym$q) begin
            gy_mag = hop_ym$q - hop_yp$q;
        end
        gz_neg = hop_zp$q < hop_zm$q;
        gz_mag = hop_zp$q - hop_zm$q;
        if (hop_zp$q < hop_zm$q) begin
            gz_mag = hop_zm$q - hop_zp$q;
        end
        o_value = centre$read_data[('h0)+:(16)];
        o_x = centre$read_data[('h10)+:(16)];
        o_y = centre$read_data[('h20)+:(16)];
        o_base_x = centre$read_data[('h30)+:(16)];
        o_base_y = centre$read_data[('h40)+:(16)];
        o_valid = centre$read_data['h50];
        o_pad = centre$read_data['h51];
        o_sr = centre$read_data['h52];
        o_er = centre$read_data['h53];
        o_edge = centre$read_data['h54];
        o_face = centre$read_data[('h55)+:(3)];
        o_dx_neg = centre$read_data['h58];
        o_dx_mag = centre$read_data[('h59)+:(16)];
        o_dy_neg = centre$read_data['h69];
        o_dy_mag = centre$read_data[('h6a)+:(16)];
        o_invalid = centre$read_data['h7a];
        if (~enabled) begin
            to_right_xm = 'h0;
            to_right_ym = 'h0;
            to_right_zm = 'h0;
            to_left_xp = 'h0;
            to_left_yp = 'h0;
            to_left_zp = 'h0;
            o_value = 'h0;
            o_x = 'h0;
            o_y = 'h0;
            o_dx_mag = 'h0;
            o_dy_mag = 'h0;
            o_base_x = 'h0;
            o_base_y = 'h0;
            gx_mag = 'h0;
            gy_mag = 'h0;
            gz_mag = 'h0;
            o_valid = 1'b0;
            o_pad = 1'b0;
            o_invalid = 1'b0;
            o_dx_neg = 1'b0;
            o_dy_neg = 1'b0;
            o_sr = 1'b0;
            o_er = 1'b0;
            o_edge = 1'b0;
            gx_neg = 1'b0;
            gy_neg = 1'b0;
            gz_neg = 1'b0;
            o_face = 'h0;
        end
    end
    
endmodule // top$lanes$3$feed$abc
module top$lanes$3$feed$abc$centre(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [122:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [122:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [122:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[15:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= write_data;
       end
    end
endmodule // top$lanes$3$feed$abc$centre
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
module top$lanes$3$feed$abc$ring_xm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$feed$abc$ring_xm
module top$lanes$3$feed$abc$ring_xp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$feed$abc$ring_xp
module top$lanes$3$feed$abc$ring_ym(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$feed$abc$ring_ym
module top$lanes$3$feed$abc$ring_yp(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$feed$abc$ring_yp
module top$lanes$3$feed$abc$ring_zm(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[65535:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[15:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[15:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$feed$abc$ring_zm
