% The variables the blocks of options_r2020a name (test file of block_options_test: duet import simulink).
threshold = 1;      % the Switch's threshold
sat_upper = 3;      % the Saturation's limits
sat_lower = -0.5;
delay_start = -4;   % the Delay's initial condition
K = [1 -1; 0.5 2];  % the Matrix(K*u) gain
